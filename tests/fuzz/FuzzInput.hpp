#pragma once
// Helpers of the fuzz targets (docs/reliability.md "Fuzzing").
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace sc::fuzz {

/// The fuzz input written to a file of this process (the readers under test take paths, as the
/// application gives them), rewritten for every input and removed at exit.
inline std::string writeInput(const std::uint8_t* data, std::size_t size, const std::string& suffix)
{
  struct TempFile {
    std::string path;
    ~TempFile()
    {
      std::error_code ec;
      std::filesystem::remove(path, ec);
    }
  };
  static const TempFile file{
      (std::filesystem::temp_directory_path() / ("sc_fuzz_" + std::to_string(::getpid()) + suffix))
          .string()};
  std::ofstream out(file.path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file.path;
}

}  // namespace sc::fuzz
