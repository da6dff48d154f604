#include <sc/io/OutputDirectory.hpp>

#include <sc/core/Collective.hpp>

#include <sc/core/Error.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <algorithm>
#include <fstream>
#include <regex>
#include <system_error>

#include <nlohmann/json.hpp>
#include <sys/resource.h>
#include <sys/statvfs.h>
#include <climits>
#include <unistd.h>

namespace sc::io {

namespace {

// The longest name of the run's files that does not depend on Output/Base name.
constexpr const char* kLongestFixedName = "stresscontact.lock.stale.4194304";

// Probe by creating a file: access(W_OK) says yes to root on read-only mounts and special
// file systems. Returns "" or the reason the file could not be created.
std::string probeWritable(const std::filesystem::path& dir)
{
  const std::string probe = (dir / (".write_probe." + std::to_string(::getpid()))).string();
  std::ofstream out(probe);
  out << "probe\n";
  out.close();
  const int err = errno;
  const bool ok = static_cast<bool>(out);
  std::remove(probe.c_str());
  return ok ? std::string() : std::string(std::strerror(err));
}

}  // namespace

void createOutputDirectory(const std::string& directory)
{
  namespace fs = std::filesystem;
  SC_THROW_IF(directory.empty(), sc::core::InputError,
              "Output/Directory is empty; give a directory name such as \"output\"");
  std::error_code ec;
  fs::create_directories(directory, ec);
  SC_THROW_IF(ec, sc::core::InputError,
              "Cannot create output directory '" << directory
                                                 << "' (Output/Directory): " << ec.message());
  SC_THROW_IF(!fs::is_directory(directory, ec), sc::core::InputError,
              "Output directory '" << directory
                                   << "' (Output/Directory) exists but is not a directory");
  const std::string why = probeWritable(directory);
  SC_THROW_IF(!why.empty(), sc::core::InputError,
              "Output directory '" << directory << "' (Output/Directory) is not writable: " << why);
}

std::vector<std::string> removeEarlierRunFiles(const std::string& directory,
                                               const std::string& baseName)
{
  namespace fs = std::filesystem;
  std::vector<std::string> bases{baseName};
  const fs::path summary = fs::path(directory) / "summary.json";
  std::error_code sec;
  if (fs::is_regular_file(summary, sec)) {
    // The base name of the run that wrote summary.json (it may differ from this run's).
    std::ifstream in(summary);
    if (in) {
      const auto j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
      if (j.is_object() && j.contains("parameters") && j["parameters"].is_object() &&
          j["parameters"].contains("Output") && j["parameters"]["Output"].is_object() &&
          j["parameters"]["Output"].contains("Base name") &&
          j["parameters"]["Output"]["Base name"].is_string()) {
        const std::string earlier = j["parameters"]["Output"]["Base name"];
        if (!earlier.empty() && earlier.find('/') == std::string::npos) bases.push_back(earlier);
      }
    }
  }
  auto quote = [](const std::string& text) {
    static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
    return std::regex_replace(text, special, R"(\$&)");
  };
  std::string alternatives =
      "summary\\.json|checkpoint\\.h5|history\\.csv|contact_cycle[0-9]+\\.csv";
  for (const auto& b : bases)
    alternatives += "|" + quote(b) + "\\.xdmf|" + quote(b) + "_c[0-9]+\\.h5";
  const std::regex ours("(" + alternatives + ")(\\.tmp\\.[0-9]+)?");

  std::vector<std::string> removed;
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) return removed;
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(directory, ec)) {
    std::error_code tec;
    if (std::regex_match(entry.path().filename().string(), ours) && !entry.is_directory(tec))
      stale.push_back(entry.path());
  }
  SC_THROW_IF(ec, sc::core::InputError,
              "Cannot list the output directory '" << directory
                                                   << "' (Output/Directory): " << ec.message());
  for (const auto& path : stale) {
    fs::remove(path, ec);
    SC_THROW_IF(ec, sc::core::InputError,
                "Cannot remove '" << path.string() << "', a file of an earlier run in the "
                                  << "output directory (Output/Directory): " << ec.message()
                                  << ". Remove it or choose another directory.");
    removed.push_back(path.filename().string());
  }
  std::sort(removed.begin(), removed.end());
  return removed;
}

std::vector<std::string> removeEarlierRunFiles(const std::string& directory,
                                               const std::string& baseName,
                                               const Teuchos::Comm<int>& comm)
{
  std::vector<std::string> removed;
  core::runOnRoot(comm, [&] { removed = removeEarlierRunFiles(directory, baseName); });
  // Every rank learns how many (the names matter only to rank 0's progress line).
  int count = static_cast<int>(removed.size());
  core::broadcast(comm, 0, count);
  if (comm.getRank() != 0) removed.assign(static_cast<std::size_t>(count), std::string());
  return removed;
}

std::vector<std::string> removeFilesAfterCycle(const std::string& directory,
                                               const std::string& baseName, int lastCycle)
{
  namespace fs = std::filesystem;
  auto quote = [](const std::string& text) {
    static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
    return std::regex_replace(text, special, R"(\$&)");
  };
  // A cycle's file (group 1: its cycle, group 2: a temporary suffix), or another temporary.
  const std::regex fields(quote(baseName) + "_c([0-9]+)\\.h5(\\.tmp\\.[0-9]+)?");
  const std::regex csv("contact_cycle([0-9]+)\\.csv(\\.tmp\\.[0-9]+)?");
  const std::regex temporary("(summary\\.json|checkpoint\\.h5|history\\.csv|" + quote(baseName) +
                             "\\.xdmf)\\.tmp\\.[0-9]+");
  std::vector<std::string> removed;
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(directory, ec)) {
    std::error_code tec;
    if (entry.is_directory(tec)) continue;
    const std::string name = entry.path().filename().string();
    std::smatch m;
    if (std::regex_match(name, m, fields) || std::regex_match(name, m, csv)) {
      if (m[2].matched || m[1].length() > 9 || std::stol(m[1].str()) > lastCycle)
        stale.push_back(entry.path());
    } else if (std::regex_match(name, temporary)) {
      stale.push_back(entry.path());
    }
  }
  SC_THROW_IF(ec, sc::core::InputError,
              "Cannot list the output directory '" << directory
                                                   << "' (--restart): " << ec.message());
  for (const auto& path : stale) {
    fs::remove(path, ec);
    SC_THROW_IF(ec, sc::core::InputError,
                "Cannot remove '" << path.string() << "', written by the restarted run after its "
                                  << "last checkpoint: " << ec.message());
    removed.push_back(path.filename().string());
  }
  std::sort(removed.begin(), removed.end());
  return removed;
}

std::vector<std::string> removeFilesAfterCycle(const std::string& directory,
                                               const std::string& baseName, int lastCycle,
                                               const Teuchos::Comm<int>& comm)
{
  std::vector<std::string> removed;
  core::runOnRoot(comm, [&] { removed = removeFilesAfterCycle(directory, baseName, lastCycle); });
  int count = static_cast<int>(removed.size());
  core::broadcast(comm, 0, count);
  if (comm.getRank() != 0) removed.assign(static_cast<std::size_t>(count), std::string());
  return removed;
}

void checkRoomForFile(const std::string& directory, const std::string& path,
                      unsigned long long bytes)
{
  auto mb = [](unsigned long long b) {
    return std::to_string((b + (1ull << 20) - 1) >> 20) + " MiB";
  };
  struct statvfs fs {};
  // File systems that report no size (f_blocks = 0: some network and virtual ones) are trusted.
  if (::statvfs(directory.c_str(), &fs) == 0 && fs.f_blocks > 0) {
    const unsigned long long available =
        static_cast<unsigned long long>(fs.f_bavail) * static_cast<unsigned long long>(fs.f_frsize);
    SC_THROW_IF(available < bytes, sc::core::Error,
                "no room for '" << path << "': it needs about " << mb(bytes)
                                << ", and the file system holding '" << directory << "' has "
                                << mb(available) << " free (disk full?)");
  }
  rlimit limit{};
  if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    SC_THROW_IF(bytes > static_cast<unsigned long long>(limit.rlim_cur), sc::core::Error,
                "no room for '" << path << "': it needs about " << mb(bytes)
                                << ", more than the file-size limit of " << limit.rlim_cur
                                << " bytes (ulimit -f)");
}

void checkRunFileNamesAreFree(const std::string& directory, const std::string& baseName)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) return;
  static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
  const std::string base = std::regex_replace(baseName, special, R"(\$&)");
  const std::regex ours("summary\\.json|checkpoint\\.h5|history\\.csv|contact_cycle[0-9]+\\.csv|" +
                        base + "\\.xdmf|" + base + "_c[0-9]+\\.h5");
  std::vector<fs::path> found;
  for (const auto& entry : fs::directory_iterator(directory, ec)) {
    if (!std::regex_match(entry.path().filename().string(), ours)) continue;
    // A symbolic link is replaced by the rename like a file; what it points to does not matter.
    std::error_code sec;
    const fs::file_type type = entry.symlink_status(sec).type();
    if (!sec && type != fs::file_type::regular && type != fs::file_type::symlink)
      found.push_back(entry.path());
  }
  SC_THROW_IF(ec, sc::core::InputError,
              "Cannot list the output directory '" << directory
                                                   << "' (Output/Directory): " << ec.message());
  if (found.empty()) return;
  std::sort(found.begin(), found.end());
  const fs::path& path = found.front();
  const bool isDirectory = fs::is_directory(fs::symlink_status(path, ec));
  SC_THROW_IF(true, sc::core::InputError,
              "'" << path.string() << "' is "
                  << (isDirectory ? "a directory" : "not a regular file (a device, pipe or socket)")
                  << ", but a run writes its file " << path.filename().string()
                  << " there (docs/output.md): rename or remove it, or choose another output "
                  << "directory (--output, Output/Directory)"
                  << (found.size() > 1
                          ? " (" + std::to_string(found.size() - 1) + " more such name(s) there)"
                          : std::string())
                  << ".");
}

void checkRunFileNamesAreFree(const std::string& directory, const std::string& baseName,
                              const Teuchos::Comm<int>& comm)
{
  core::runOnRoot(comm, [&] {
    checkRunFileNameLengths(directory, baseName);
    checkRunFileNamesAreFree(directory, baseName);
  });
}

void checkRunFileNameLengths(const std::string& directory, const std::string& baseName)
{
  namespace fs = std::filesystem;
  // Linux pids are below 2^22 (pid_max), so at most 7 digits; cycles have 4 (Adaptivity/Cycles
  // is at most 100).
  const std::string suffix = "_c0000.h5.tmp.4194304";
  const std::string longestName =
      std::max(baseName + suffix, std::string(kLongestFixedName),
               [](const auto& a, const auto& b) { return a.size() < b.size(); });
  std::error_code ec;
  fs::path existing = directory;
  while (!fs::exists(existing, ec) && existing.has_parent_path() &&
         existing.parent_path() != existing)
    existing = existing.parent_path();
  if (!fs::exists(existing, ec)) existing = ".";
  long nameMax = ::pathconf(existing.c_str(), _PC_NAME_MAX);
  long pathMax = ::pathconf(existing.c_str(), _PC_PATH_MAX);
  if (nameMax <= 0) nameMax = NAME_MAX;
  if (pathMax <= 0) pathMax = PATH_MAX;
  const long nameLength = static_cast<long>(longestName.size());
  SC_THROW_IF(nameLength > nameMax, sc::core::InputError,
              "Output/Base name is " << baseName.size() << " characters long: the run's field "
                                     << "files, <Base name>_c<NNNN>.h5 written as "
                                     << "<Base name>_c<NNNN>.h5.tmp.<pid>, would have names of up "
                                     << "to " << nameLength << " characters, above the limit of "
                                     << nameMax << " per file name (NAME_MAX) of the file system "
                                     << "holding '" << existing.string() << "'. Give a Base name "
                                     << "of at most " << nameMax - static_cast<long>(suffix.size())
                                     << " characters.");
  const std::string longestPath = (fs::path(directory) / longestName).string();
  const long pathLength = static_cast<long>(longestPath.size());
  SC_THROW_IF(pathLength >= pathMax, sc::core::InputError,
              "the output directory (Output/Directory, "
                  << directory.size() << " characters) is "
                  << "too long: with the run's longest file name, " << longestName
                  << ", the path would have " << pathLength << " characters, above the limit of "
                  << pathMax - 1 << " per path (PATH_MAX). Choose a shorter directory or Base "
                  << "name. The directory: '" << directory << "'");
}

void checkOutputDirectory(const std::string& directory)
{
  namespace fs = std::filesystem;
  SC_THROW_IF(directory.empty(), sc::core::InputError,
              "Output/Directory is empty; give a directory name such as \"output\"");
  std::error_code ec;
  fs::path p = fs::absolute(directory, ec);
  if (ec) p = directory;
  // The directory itself if it exists, else the nearest existing ancestor (where it would be
  // created).
  while (!fs::exists(p, ec) && p.has_parent_path() && p.parent_path() != p)
    p = p.parent_path();
  const bool self = fs::equivalent(p, fs::absolute(directory, ec), ec);
  SC_THROW_IF(!fs::is_directory(p, ec), sc::core::InputError,
              (self ? "Output directory '" + directory +
                          "' (Output/Directory) exists but is not a directory"
                    : "Cannot create output directory '" + directory + "' (Output/Directory): '" +
                          p.string() + "' is not a directory"));
  const std::string why = probeWritable(p);
  SC_THROW_IF(
      !why.empty(), sc::core::InputError,
      (self ? "Output directory '" + directory + "' (Output/Directory) is not writable: " + why
            : "Cannot create output directory '" + directory + "' (Output/Directory): '" +
                  p.string() + "' is not writable: " + why));
}

void checkOutputDirectory(const std::string& directory, const Teuchos::Comm<int>& comm)
{
  core::runOnRoot(comm, [&] { checkOutputDirectory(directory); });
}

void createOutputDirectory(const std::string& directory, const Teuchos::Comm<int>& comm)
{
  core::runOnRoot(comm, [&] { createOutputDirectory(directory); });
}

}  // namespace sc::io
