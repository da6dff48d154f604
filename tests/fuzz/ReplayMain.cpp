// main() of the replay executables fuzz_replay_<target>: feeds each file given (or each file of
// each directory given, in name order) to the fuzz target's LLVMFuzzerTestOneInput, as libFuzzer
// would, without libFuzzer. Built with the ordinary compiler in every test build: CTest replays
// the seed corpus and every input the fuzzer found (tests/fuzz/regressions/<target>/), so a
// finding, once fixed, stays a regression test. An input that crashes aborts this program.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include <sc/core/FloatingPointTraps.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char* argv[])
{
  sc::core::enableFloatingPointTrapsFromEnvironment();
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    if (fs::is_directory(argv[i])) {
      std::vector<fs::path> in(fs::directory_iterator(argv[i]), fs::directory_iterator{});
      std::sort(in.begin(), in.end());
      for (const auto& f : in)
        if (fs::is_regular_file(f)) files.push_back(f);
    } else {
      files.emplace_back(argv[i]);
    }
  }
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    if (!in) {
      std::cerr << "cannot read " << f << "\n";
      return 1;
    }
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::cout << "input " << f.string() << " (" << bytes.size() << " bytes)" << std::endl;
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << files.size() << " inputs replayed, none crashed" << std::endl;
  return files.empty() ? 1 : 0;
}
