// libFuzzer target: a checkpoint.h5 read by sc::io::CheckpointFile::read, as `--restart DIR` reads
// it (HDF5's reader, then our checks: format attribute, dataset kinds, the checksum of every
// dataset). sc::core::InputError is expected; anything else is a finding. HDF5 itself is not
// instrumented: coverage feedback comes from our code only, and a crash inside HDF5's parser
// on a damaged file is a finding to report there (the checksum guards the data, not HDF5's own
// structures).
#include <cstddef>
#include <cstdint>
#include <string>

#include <sc/core/Error.hpp>
#include <sc/io/CheckpointFile.hpp>

#include "FuzzInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string path = sc::fuzz::writeInput(data, size, ".h5");
  try {
    const auto cp = sc::io::CheckpointFile::read(path);
    (void)cp.checksum();
  } catch (const sc::core::InputError&) {
  }
  return 0;
}
