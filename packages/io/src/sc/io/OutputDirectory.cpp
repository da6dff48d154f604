#include <sc/io/OutputDirectory.hpp>

#include <sc/io/Collective.hpp>

#include <sc/core/Error.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace sc::io {

void createOutputDirectory(const std::string& directory)
{
  namespace fs = std::filesystem;
  SC_THROW_IF(directory.empty(), sc::core::InputError,
              "Output/Directory is empty; give a directory name such as \"output\"");
  std::error_code ec;
  fs::create_directories(directory, ec);
  SC_THROW_IF(ec, sc::core::InputError,
              "Cannot create output directory '" << directory << "' (Output/Directory): "
                                                 << ec.message());
  SC_THROW_IF(!fs::is_directory(directory, ec), sc::core::InputError,
              "Output directory '" << directory << "' (Output/Directory) exists but is not a directory");
  // Probe by creating a file: access(W_OK) says yes to root on read-only mounts and special
  // file systems.
  const std::string probe =
      (fs::path(directory) / (".write_probe." + std::to_string(::getpid()))).string();
  {
    std::ofstream out(probe);
    out << "probe\n";
    out.close();
    if (!out) {
      const int err = errno;
      std::remove(probe.c_str());
      SC_THROW_IF(true, sc::core::InputError,
                  "Output directory '" << directory << "' (Output/Directory) is not writable: "
                                       << std::strerror(err));
    }
  }
  std::remove(probe.c_str());
}

void createOutputDirectory(const std::string& directory, const Teuchos::Comm<int>& comm)
{
  runOnRoot(comm, [&] { createOutputDirectory(directory); });
}

}  // namespace sc::io
