// AtomicFile, writeFileAtomically and createOutputDirectory.
#include <sc/io/AtomicFile.hpp>
#include <sc/io/OutputDirectory.hpp>

#include "TestDirectory.hpp"

#include <sc/core/Error.hpp>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

using sc::io::test::freshDirectory;
using sc::io::test::temporaries;

std::string readAll(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEUCHOS_UNIT_TEST(AtomicFile, WritesReplacesAndLeavesNoTemporary)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = freshDirectory(*comm, "atomic");
  if (comm->getRank() != 0) return;
  const std::string path = dir + "/a.txt";
  sc::io::writeFileAtomically(path, "first\n");
  TEST_EQUALITY(readAll(path), "first\n");
  sc::io::writeFileAtomically(path, std::string("second\0x", 8));
  TEST_EQUALITY(readAll(path), std::string("second\0x", 8));
  TEST_EQUALITY(temporaries(dir).size(), 0u);
}

TEUCHOS_UNIT_TEST(AtomicFile, AbandonedWriteKeepsOldContentAndRemovesTemporary)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = freshDirectory(*comm, "atomic_abandon");
  if (comm->getRank() != 0) return;
  const std::string path = dir + "/b.txt";
  sc::io::writeFileAtomically(path, "complete\n");
  {
    sc::io::AtomicFile file(path);
    file.stream() << "half-writ";
    TEST_ASSERT(std::filesystem::exists(file.temporaryPath()));
    TEST_EQUALITY(readAll(path), "complete\n");  // not replaced before commit
    // leaves scope without commit(), as when an exception unwinds
  }
  TEST_EQUALITY(readAll(path), "complete\n");
  TEST_EQUALITY(temporaries(dir).size(), 0u);
}

TEUCHOS_UNIT_TEST(AtomicFile, UnwritableTargetThrowsNamingIt)
{
  const std::string path = "/proc/forbidden/x.txt";
  try {
    sc::io::writeFileAtomically(path, "x");
    TEST_ASSERT(false);
  } catch (const sc::core::Error& e) {
    TEST_ASSERT(std::string(e.what()).find(path) != std::string::npos);
  }
}

TEUCHOS_UNIT_TEST(OutputDirectory, CreatesNestedDirectories)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = freshDirectory(*comm, "outdir") + "/a/b/c";
  sc::io::createOutputDirectory(dir, *comm);
  TEST_ASSERT(std::filesystem::is_directory(dir));
  TEST_EQUALITY(std::distance(std::filesystem::directory_iterator(dir),
                              std::filesystem::directory_iterator()),
                0);  // the writability probe is removed
  // Every rank has looked before rank 0 probes the directory again: the second call's probe file
  // would otherwise stand in the directory while a slower rank counts its entries.
  comm->barrier();
  sc::io::createOutputDirectory(dir, *comm);  // existing directory: fine
}

TEUCHOS_UNIT_TEST(OutputDirectory, UnusableDirectoryThrowsInputErrorOnAllRanks)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = freshDirectory(*comm, "outdir_bad");
  const std::string regularFile = base + "/plain_file";
  if (comm->getRank() == 0) std::ofstream(regularFile) << "not a directory\n";
  comm->barrier();
  for (const std::string& bad :
       {regularFile + "/sub", regularFile, std::string("/proc/forbidden")}) {
    bool threw = false;
    try {
      sc::io::createOutputDirectory(bad, *comm);
    } catch (const sc::core::InputError& e) {
      threw = true;
      TEST_ASSERT(std::string(e.what()).find(bad) != std::string::npos);
      out << e.what() << "\n";
    }
    TEST_ASSERT(threw);
  }
}

}  // namespace
