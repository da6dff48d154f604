// The output directory: a run removes the files of an earlier run (and nothing else), and
// --check's probe creates nothing (docs/output.md "An earlier run's files", docs/reliability.md).
#include <sc/io/OutputDirectory.hpp>

#include <sc/core/Error.hpp>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

// A fresh directory per rank count and rank: each rank works alone, and the _np1/_np2/_np4 tests
// share one working directory and run side by side when ctest -j has room for both. Named by the
// rank alone, rank 0 of the 1-rank and of the 2-rank test would share a directory and empty it
// under each other.
std::string freshDirectory(const std::string& name)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = "io_test_np" + std::to_string(comm->getSize()) + "/output_directory_" +
                          name + "_r" + std::to_string(comm->getRank());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void touch(const std::string& path, const std::string& text = "x\n")
{
  std::ofstream(path) << text;
}

TEUCHOS_UNIT_TEST(OutputDirectory, RemovesOnlyTheFilesOfAnEarlierRun)
{
  const std::string dir = freshDirectory("stale");
  // An earlier run with Base name "old": its summary records it.
  touch(dir + "/summary.json", R"({"parameters": {"Output": {"Base name": "old"}}})");
  for (const char* f :
       {"old.xdmf", "old_c0000.h5", "old_c0001.h5", "solution.xdmf", "solution_c0003.h5",
        "contact_cycle0.csv", "contact_cycle12.csv", "solution_c0002.h5.tmp.4242",
        "summary.json.tmp.17", "history.csv", "history.csv.tmp.99"})
    touch(dir + "/" + f);
  // Not ours: kept.
  const std::vector<std::string> kept = {"notes.txt", "mesh.msh",          "other.xdmf",
                                         "old_c.h5",  "contact_cycle.csv", "solution_c0001.h5.bak",
                                         "my.json",   "history_old.csv"};
  for (const auto& f : kept)
    touch(dir + "/" + f);
  fs::create_directories(dir + "/contact_cycle3.csv");  // a directory is never removed

  const auto removed = sc::io::removeEarlierRunFiles(dir, "solution");
  TEST_COMPARE_ARRAYS(removed, (std::vector<std::string>{
                                   "contact_cycle0.csv", "contact_cycle12.csv", "history.csv",
                                   "history.csv.tmp.99", "old.xdmf", "old_c0000.h5", "old_c0001.h5",
                                   "solution.xdmf", "solution_c0002.h5.tmp.4242",
                                   "solution_c0003.h5", "summary.json", "summary.json.tmp.17"}));
  for (const auto& f : kept)
    TEST_ASSERT(fs::exists(dir + "/" + f));
  TEST_ASSERT(fs::is_directory(dir + "/contact_cycle3.csv"));
  // Nothing left of ours: a second call removes nothing; a missing directory is no error.
  TEST_EQUALITY(sc::io::removeEarlierRunFiles(dir, "solution").size(), 0u);
  TEST_EQUALITY(sc::io::removeEarlierRunFiles(dir + "/missing", "solution").size(), 0u);
  fs::remove_all(dir);
}

TEUCHOS_UNIT_TEST(OutputDirectory, CheckCreatesNothingAndNamesTheProblem)
{
  const std::string dir = freshDirectory("check");
  sc::io::checkOutputDirectory(dir);               // exists, writable
  sc::io::checkOutputDirectory(dir + "/new/sub");  // would be created
  TEST_ASSERT(!fs::exists(dir + "/new"));
  TEST_EQUALITY(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0);
  touch(dir + "/file");
  try {
    sc::io::checkOutputDirectory(dir + "/file/sub");
    TEST_ASSERT(false);
  } catch (const sc::core::InputError& e) {
    out << e.what() << "\n";
    TEST_ASSERT(std::string(e.what()).find("is not a directory") != std::string::npos);
  }
  TEST_THROW(sc::io::checkOutputDirectory(dir + "/file"), sc::core::InputError);
  TEST_THROW(sc::io::checkOutputDirectory(""), sc::core::InputError);
  fs::remove_all(dir);
}

TEUCHOS_UNIT_TEST(OutputDirectory, RunFileNamesTakenByDirectoriesAreInputErrors)
{
  const std::string dir = freshDirectory("names");
  auto error = [&] {
    try {
      sc::io::checkRunFileNamesAreFree(dir, "fields");
    } catch (const sc::core::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // Regular files, links and other names are no obstacle; a missing directory is none either.
  touch(dir + "/summary.json");
  fs::create_symlink(".", dir + "/checkpoint.h5");
  fs::create_directories(dir + "/solution_c0000.h5");  // not this run's base name
  fs::create_directories(dir + "/fields_c.h5");
  TEST_EQUALITY(error(), "");
  sc::io::checkRunFileNamesAreFree(dir + "/missing", "fields");
  for (const std::string name :
       {"fields.xdmf", "fields_c0012.h5", "contact_cycle3.csv", "history.csv"}) {
    fs::create_directories(dir + "/" + name);
    const std::string e = error();
    out << e << "\n";
    TEST_ASSERT(e.find("'" + dir + "/" + name + "' is a directory, but a run writes its file " +
                       name + " there") != std::string::npos);
    fs::remove(dir + "/" + name);
  }
  fs::remove(dir + "/summary.json");
  fs::create_directories(dir + "/summary.json");
  fs::create_directories(dir + "/fields.xdmf");
  const std::string e = error();
  out << e << "\n";
  TEST_ASSERT(e.find("'" + dir + "/fields.xdmf' is a directory") != std::string::npos);
  TEST_ASSERT(e.find("(1 more such name(s) there)") != std::string::npos);
  // An earlier run's summary.json that is a directory is neither read nor removed.
  TEST_EQUALITY(sc::io::removeEarlierRunFiles(dir, "fields").size(), 0u);
  fs::remove_all(dir);
}

TEUCHOS_UNIT_TEST(OutputDirectory, FileNameLengthsAreChecked)
{
  const std::string dir = freshDirectory("lengths");
  auto error = [](const std::string& directory, const std::string& base) {
    try {
      sc::io::checkRunFileNameLengths(directory, base);
    } catch (const sc::core::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // "<base>_c0000.h5.tmp.<7-digit pid>" adds 21 characters to the Base name.
  const long nameMax = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  const long longest = nameMax - 21;
  TEST_EQUALITY(error(dir, std::string(static_cast<std::size_t>(longest), 'b')), "");
  const std::string e = error(dir, std::string(static_cast<std::size_t>(longest + 1), 'b'));
  out << e << "\n";
  TEST_ASSERT(e.find("Output/Base name is " + std::to_string(longest + 1) + " characters long") !=
              std::string::npos);
  TEST_ASSERT(e.find("above the limit of " + std::to_string(nameMax) +
                     " per file name (NAME_MAX)") != std::string::npos);
  TEST_ASSERT(e.find("at most " + std::to_string(longest) + " characters") != std::string::npos);
  // A directory (not created) whose files' paths would exceed PATH_MAX.
  std::string deep = dir;
  while (deep.size() < 4080)
    deep += "/" + std::string(100, 'd');
  const std::string p = error(deep, "solution");
  out << p.substr(0, 200) << "\n";
  TEST_ASSERT(p.find("the output directory (Output/Directory, " + std::to_string(deep.size()) +
                     " characters) is too long") != std::string::npos);
  TEST_ASSERT(p.find("(PATH_MAX)") != std::string::npos);
  TEST_EQUALITY(error(dir + "/" + std::string(200, 'd'), "solution"), "");
  TEST_EQUALITY(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0);
  fs::remove_all(dir);
}

}  // namespace
