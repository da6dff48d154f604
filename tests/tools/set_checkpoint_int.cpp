// set_checkpoint_int FILE NAME VALUE: sets the integer entry NAME of the checkpoint FILE to the
// single number VALUE and writes the file again (with its checksum), as a checkpoint of another
// version would be. For the restart error tests (tests/LoadSteps.py, case restart-errors: a
// checkpoint of an older format is refused naming 'checkpoint_version').
#include <sc/io/CheckpointFile.hpp>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

int main(int argc, char** argv)
{
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s FILE NAME VALUE\n", argv[0]);
    return 2;
  }
  try {
    auto cp = sc::io::CheckpointFile::read(argv[1]);
    if (cp.ints(argv[2]).size() != 1) {
      std::fprintf(stderr, "%s: '%s' is not a single integer\n", argv[0], argv[2]);
      return 1;
    }
    cp.setInts(argv[2], {std::atoll(argv[3])});
    cp.write(argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", argv[0], e.what());
    return 1;
  }
  return 0;
}
