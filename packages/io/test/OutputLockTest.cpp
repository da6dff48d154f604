// One run per output directory (io/OutputLock.hpp): a second lock is refused naming the
// directory and the owner's pid, a stale lock is taken over, the lock goes at the end and is
// never removed by the cleaning of an earlier run's files. Collective: 1, 2 and 4 ranks.
#include <sc/io/OutputDirectory.hpp>
#include <sc/io/OutputLock.hpp>

#include <sc/core/Error.hpp>

#include "TestDirectory.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

std::string readFile(const std::string& path)
{
  std::ifstream in(path);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

std::string host()
{
  char buffer[256] = {};
  ::gethostname(buffer, sizeof buffer - 1);
  return buffer;
}

// Rank 0's pid, on every rank.
long rootPid(const Teuchos::Comm<int>& comm)
{
  long pid = static_cast<long>(::getpid());
  Teuchos::broadcast<int, long>(comm, 0, &pid);
  return pid;
}

// The message of the InputError that constructing a lock of `dir` throws ("" if none).
std::string lockError(const Teuchos::Comm<int>& comm, const std::string& dir)
{
  try {
    sc::io::OutputLock lock(comm, dir);
  } catch (const sc::core::InputError& e) {
    return e.what();
  }
  return "";
}

TEUCHOS_UNIT_TEST(OutputLock, OneRunPerDirectory)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank();
  const std::string dir = sc::io::test::freshDirectory(*comm, "lock_one_run");
  const std::string path = dir + "/stresscontact.lock";
  const long pid = rootPid(*comm);
  {
    const sc::io::OutputLock lock(*comm, dir);
    TEST_EQUALITY(lock.takenOver(), "");
    if (rank == 0) {
      const std::string text = readFile(path);
      out << text;
      TEST_ASSERT(contains(text, "pid " + std::to_string(pid) + "\nhost " + host() + "\nstart "));
    }
    // A second run (here a second lock of this live process) is refused on every rank.
    const std::string e = lockError(*comm, dir);
    out << e << "\n";
    TEST_ASSERT(contains(e, "the output directory '" + dir +
                                "' is in use by another StressContact run: process " +
                                std::to_string(pid) + " on this host (" + host() +
                                ") holds its lock '" + path + "'"));
    TEST_THROW(sc::io::checkOutputLock(dir, *comm), sc::core::InputError);
    // Removing an earlier run's files leaves the lock alone.
    if (rank == 0) {
      std::ofstream(dir + "/summary.json") << "{}\n";
      const auto removed = sc::io::removeEarlierRunFiles(dir, "solution");
      TEST_EQUALITY(removed.size(), 1u);
      TEST_ASSERT(fs::exists(path));
    }
    comm->barrier();
  }
  // Released at the end.
  if (rank == 0) TEST_ASSERT(!fs::exists(path));
  sc::io::checkOutputLock(dir, *comm);
  comm->barrier();
}

TEUCHOS_UNIT_TEST(OutputLock, StaleLocksAreTakenOver)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank();
  const std::string dir = sc::io::test::freshDirectory(*comm, "lock_stale");
  const std::string path = dir + "/stresscontact.lock";
  // No process has the pid pid_max (pids are below it): the lock of a run that was killed.
  long deadPid = 4194304;
  std::ifstream("/proc/sys/kernel/pid_max") >> deadPid;
  // A dead pid, and this process's pid with another start time (a pid used again).
  for (const std::string& owner :
       {"pid " + std::to_string(deadPid) + "\nhost " + host() + "\nstart 5\n",
        "pid " + std::to_string(rootPid(*comm)) + "\nhost " + host() + "\nstart 1\n"}) {
    if (rank == 0) std::ofstream(path) << owner;
    comm->barrier();
    {
      const sc::io::OutputLock lock(*comm, dir);
      if (rank == 0) {
        out << lock.takenOver() << "\n";
        TEST_ASSERT(contains(lock.takenOver(),
                             "took over the stale lock '" + path + "' of process " +
                                 owner.substr(4, owner.find('\n') - 4) + " on this host"));
        TEST_ASSERT(contains(readFile(path), "pid " + std::to_string(::getpid()) + "\n"));
        // Nothing else is left in the directory (the stale lock was moved aside, then removed).
        TEST_EQUALITY(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
      } else {
        TEST_EQUALITY(lock.takenOver(), "");
      }
      comm->barrier();
    }
    if (rank == 0) TEST_ASSERT(!fs::exists(path));
    comm->barrier();
  }
  // A start time of -1 is unknown: this live pid is then taken at its word (alive).
  if (rank == 0)
    std::ofstream(path) << "pid " << ::getpid() << "\nhost " << host() << "\nstart -1\n";
  comm->barrier();
  TEST_ASSERT(contains(lockError(*comm, dir), "is in use by another StressContact run"));
  comm->barrier();
}

TEUCHOS_UNIT_TEST(OutputLock, LocksThatCannotBeCheckedAreRefused)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank();
  const std::string dir = sc::io::test::freshDirectory(*comm, "lock_refused");
  const std::string path = dir + "/stresscontact.lock";
  // A run on another host: alive or not cannot be told from here.
  if (rank == 0) std::ofstream(path) << "pid 1\nhost another-host.example\nstart 5\n";
  comm->barrier();
  std::string e = lockError(*comm, dir);
  out << e << "\n";
  TEST_ASSERT(
      contains(e, "process 1 on host 'another-host.example' holds its lock '" + path +
                      "' (another host: whether that run is still alive cannot be checked"));
  TEST_THROW(sc::io::checkOutputLock(dir, *comm), sc::core::InputError);
  // A file of that name that is no lock, and a directory of that name.
  if (rank == 0) std::ofstream(path) << "my notes\n";
  comm->barrier();
  e = lockError(*comm, dir);
  out << e << "\n";
  TEST_ASSERT(contains(e, "holds '" + path +
                              "', which is not a StressContact lock file (it names no "
                              "process id and host)"));
  if (rank == 0) {
    fs::remove(path);
    fs::create_directory(path);
  }
  comm->barrier();
  TEST_ASSERT(contains(lockError(*comm, dir),
                       "which is not a StressContact lock file (it is a directory)"));
  // The files were left as they were.
  if (rank == 0) TEST_ASSERT(fs::is_directory(path));
  comm->barrier();
}

TEUCHOS_UNIT_TEST(OutputLock, OnlyItsOwnLockIsRemoved)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank();
  const std::string dir = sc::io::test::freshDirectory(*comm, "lock_own");
  const std::string path = dir + "/stresscontact.lock";
  {
    const sc::io::OutputLock lock(*comm, dir);
    // Someone replaced the lock (e.g. removed it by hand and started another run).
    if (rank == 0) std::ofstream(path) << "pid 1\nhost another-host.example\n";
    comm->barrier();
  }
  if (rank == 0) TEST_ASSERT(contains(readFile(path), "another-host.example"));
  comm->barrier();
}

}  // namespace
