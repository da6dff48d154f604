#pragma once
// A scratch directory per test and rank count (the _np1/_np2/_np4 tests may run concurrently),
// emptied first so that files of an earlier run cannot make a test pass.

#include <Teuchos_Comm.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace sc::io::test {

inline std::string freshDirectory(const Teuchos::Comm<int>& comm, const std::string& name)
{
  const std::string dir = "io_test_np" + std::to_string(comm.getSize()) + "/" + name;
  comm.barrier();
  if (comm.getRank() == 0) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  comm.barrier();
  return dir;
}

/// Names of files in \p dir that contain ".tmp" (left-over temporaries).
inline std::vector<std::string> temporaries(const std::string& dir)
{
  std::vector<std::string> found;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp") != std::string::npos)
      found.push_back(e.path().string());
  return found;
}

}  // namespace sc::io::test
