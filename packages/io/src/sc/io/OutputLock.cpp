#include <sc/io/OutputLock.hpp>

#include <sc/core/Collective.hpp>

#include <sc/core/Error.hpp>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace sc::io {

namespace {

// What a lock file says about its owner.
struct Owner {
  long pid = 0;
  std::string host;
  long long start = -1;  ///< start time of the process (clock ticks after boot); -1: unknown
};

std::string hostName()
{
  char buffer[256] = {};
  if (::gethostname(buffer, sizeof buffer - 1) != 0 || buffer[0] == '\0') return "unknown";
  return buffer;
}

// State and start time of process `pid` (/proc/<pid>/stat, fields 3 and 22); false where /proc
// does not say (not Linux, or no such process).
bool processStat(long pid, char& state, long long& start)
{
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!in || !std::getline(in, line)) return false;
  const auto close = line.rfind(')');  // the command name may hold blanks and parentheses
  if (close == std::string::npos) return false;
  std::istringstream fields(line.substr(close + 1));
  std::string field;
  for (int i = 3; i <= 22 && fields >> field; ++i) {
    if (i == 3) state = field[0];
    if (i == 22) {
      start = std::atoll(field.c_str());
      return true;
    }
  }
  return false;
}

Owner thisProcess()
{
  Owner me;
  me.pid = static_cast<long>(::getpid());
  me.host = hostName();
  char state = 0;
  processStat(me.pid, state, me.start);
  return me;
}

std::string lockText(const Owner& o)
{
  return "pid " + std::to_string(o.pid) + "\nhost " + o.host + "\nstart " +
         std::to_string(o.start) + "\n";
}

bool parseLock(const std::string& text, Owner& o)
{
  bool pid = false, host = false;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream l(line);
    std::string key;
    l >> key;
    if (key == "pid")
      pid = static_cast<bool>(l >> o.pid) && o.pid > 0;
    else if (key == "host")
      host = static_cast<bool>(std::getline(l >> std::ws, o.host)) && !o.host.empty();
    else if (key == "start" && !(l >> o.start))
      o.start = -1;
  }
  return pid && host;
}

enum class Status { Alive, Dead, OtherHost };

Status ownerStatus(const Owner& o)
{
  if (o.host != hostName()) return Status::OtherHost;
  if (::kill(static_cast<pid_t>(o.pid), 0) != 0 && errno == ESRCH) return Status::Dead;
  char state = 0;
  long long start = -1;
  if (processStat(o.pid, state, start)) {
    if (state == 'Z' || state == 'X') return Status::Dead;  // exited, not yet reaped by its parent
    if (o.start >= 0 && start != o.start)
      return Status::Dead;  // the pid now belongs to another process
  }
  return Status::Alive;
}

enum class Read { Lock, Missing, NotALock };

// Read the lock file at `path` into `text` and `owner`. A lock file is empty for the instant
// between its creation and its owner's write: an unreadable one is read again for up to a second.
Read readLock(const std::string& path, std::string& text, Owner& owner, std::string& why)
{
  for (int attempt = 0;; ++attempt) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) {
      if (errno == ENOENT || errno == ENOTDIR) return Read::Missing;
      why = std::strerror(errno);
      return Read::NotALock;
    }
    if (!S_ISREG(st.st_mode)) {
      why = S_ISDIR(st.st_mode) ? "it is a directory" : "it is not a regular file";
      return Read::NotALock;
    }
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
      if (errno == ENOENT) return Read::Missing;
      why = std::strerror(errno);
      return Read::NotALock;
    }
    text.clear();
    char buffer[4096];
    for (ssize_t n; text.size() < 65536 && (n = ::read(fd, buffer, sizeof buffer)) > 0;)
      text.append(buffer, static_cast<std::size_t>(n));
    ::close(fd);
    owner = Owner{};
    if (parseLock(text, owner)) return Read::Lock;
    if (attempt == 20) {
      why = text.empty() ? "it is empty" : "it names no process id and host";
      return Read::NotALock;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

std::string notALock(const std::string& directory, const std::string& path, const std::string& why)
{
  std::ostringstream os;
  os << "the output directory '" << directory << "' holds '" << path
     << "', which is not a StressContact lock file (" << why
     << "). A run keeps the pid and host of its process in that file while it writes into the "
     << "directory; if no run is using '" << directory << "', remove '" << path
     << "', or choose another output directory (--output, Output/Directory).";
  return os.str();
}

std::string inUse(const std::string& directory, const std::string& path, const Owner& owner,
                  Status status)
{
  std::ostringstream os;
  os << "the output directory '" << directory << "' is in use by another StressContact run: "
     << "process " << owner.pid;
  if (status == Status::OtherHost)
    os << " on host '" << owner.host << "' holds its lock '" << path
       << "' (another host: whether that run is still alive cannot be checked from here; if it is "
       << "not, remove '" << path << "')";
  else
    os << " on this host (" << owner.host << ") holds its lock '" << path << "'";
  os << ". Wait for that run to end, or choose another output directory (--output, "
     << "Output/Directory): two runs in one directory would mix their files.";
  return os.str();
}

// Rank 0's work of the constructor: returns the description of a stale lock taken over, or "".
std::string acquire(const std::string& directory, const std::string& path)
{
  const Owner me = thisProcess();
  std::string takenOver;
  for (int attempt = 0; attempt < 5; ++attempt) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd >= 0) {
      const std::string text = lockText(me);
      const bool written =
          ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
      const int err = errno;
      const bool closed = ::close(fd) == 0;
      if (!written || !closed) {
        ::unlink(path.c_str());
        SC_THROW_IF(true, sc::core::InputError,
                    "Cannot write the lock file '" << path << "' in the output directory "
                                                   << "(Output/Directory): " << std::strerror(err));
      }
      return takenOver;
    }
    const int err = errno;
    SC_THROW_IF(err != EEXIST, sc::core::InputError,
                "Cannot create the lock file '" << path << "' in the output directory "
                                                << "(Output/Directory): " << std::strerror(err));
    std::string text, why;
    Owner owner;
    const Read read = readLock(path, text, owner, why);
    if (read == Read::Missing) continue;  // its run removed it an instant ago
    SC_THROW_IF(read == Read::NotALock, sc::core::InputError, notALock(directory, path, why));
    const Status status = ownerStatus(owner);
    SC_THROW_IF(status != Status::Dead, sc::core::InputError,
                inUse(directory, path, owner, status));
    // Stale. Move it aside first and look at what was moved: if another run took the stale lock
    // over in between, the file moved is that run's live lock, and goes back.
    const std::string aside = path + ".stale." + std::to_string(me.pid);
    if (::rename(path.c_str(), aside.c_str()) != 0) {
      const int renameErr = errno;
      if (renameErr == ENOENT) continue;
      SC_THROW_IF(true, sc::core::InputError,
                  "Cannot remove the stale lock '"
                      << path << "' (its process " << owner.pid
                      << " no longer runs): " << std::strerror(renameErr));
    }
    std::string movedText, movedWhy;
    Owner moved;
    if (readLock(aside, movedText, moved, movedWhy) == Read::Lock && movedText != text) {
      ::rename(aside.c_str(), path.c_str());
      SC_THROW_IF(true, sc::core::InputError, inUse(directory, path, moved, ownerStatus(moved)));
    }
    ::unlink(aside.c_str());
    std::ostringstream os;
    os << "took over the stale lock '" << path << "' of process " << owner.pid << " on this host ("
       << owner.host << "), which no longer runs (a run there was killed or crashed)";
    takenOver = os.str();
  }
  SC_THROW_IF(true, sc::core::InputError,
              "Cannot take the lock '" << path << "': other runs keep starting in the output "
                                       << "directory '" << directory << "'.");
  return takenOver;
}

}  // namespace

OutputLock::OutputLock(const Teuchos::Comm<int>& comm, std::string directory)
    : directory_(std::move(directory)),
      path_((std::filesystem::path(directory_) / kOutputLockName).string())
{
  core::runOnRoot(comm, [&] {
    takenOver_ = acquire(directory_, path_);
    held_ = true;
  });
}

OutputLock::~OutputLock()
{
  if (!held_) return;
  try {
    // Only if it is still ours: never remove the lock of a run that took over by mistake.
    std::string text, why;
    Owner owner;
    const Owner me = thisProcess();
    if (readLock(path_, text, owner, why) == Read::Lock && owner.pid == me.pid &&
        owner.host == me.host)
      ::unlink(path_.c_str());
  } catch (...) {
    // A destructor must not throw; a lock left behind is recognised as stale by the next run.
  }
}

void checkOutputLock(const std::string& directory)
{
  const std::string path = (std::filesystem::path(directory) / kOutputLockName).string();
  std::string text, why;
  Owner owner;
  const Read read = readLock(path, text, owner, why);
  if (read == Read::Missing) return;
  SC_THROW_IF(read == Read::NotALock, sc::core::InputError, notALock(directory, path, why));
  const Status status = ownerStatus(owner);
  SC_THROW_IF(status != Status::Dead, sc::core::InputError, inUse(directory, path, owner, status));
}

void checkOutputLock(const std::string& directory, const Teuchos::Comm<int>& comm)
{
  core::runOnRoot(comm, [&] { checkOutputLock(directory); });
}

}  // namespace sc::io
