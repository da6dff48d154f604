// CheckpointFile (docs/output.md "checkpoint.h5"): round trip, atomic replacement, errors naming
// the file; removeFilesAfterCycle.
#include <sc/io/CheckpointFile.hpp>

#include <hdf5.h>
#include <sc/io/OutputDirectory.hpp>

#include "TestDirectory.hpp"

#include <sc/core/Error.hpp>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <functional>
#include <limits>

namespace {

using sc::io::test::freshDirectory;
using sc::io::test::temporaries;

bool contains(const std::string& text, const std::string& what)
{
  return text.find(what) != std::string::npos;
}

std::string inputErrorOf(const std::function<void()>& f)
{
  try {
    f();
  } catch (const sc::core::InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEUCHOS_UNIT_TEST(CheckpointFile, RoundTripIsExactAndReplacesAtomically)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = freshDirectory(*comm, "checkpoint");
  if (comm->getRank() != 0) return;
  const std::string path = dir + "/checkpoint.h5";
  sc::io::CheckpointFile cp;
  const std::vector<double> x = {0.1, -1e-300, std::numeric_limits<double>::max(), 1.0 / 3.0};
  const std::vector<long long> n = {0, -1, (1LL << 62) + 7};
  cp.setDoubles("x", x);
  cp.setInts("n", n);
  cp.setInts("empty", {});
  cp.setString("s", std::string("{\"a\": \"\xc3\xa9\"}\0z", 15));
  cp.write(path);
  auto back = sc::io::CheckpointFile::read(path);
  TEST_ASSERT(back.doubles("x") == x);
  TEST_ASSERT(back.ints("n") == n);
  TEST_EQUALITY(back.ints("empty").size(), 0u);
  TEST_EQUALITY(back.string("s"), std::string("{\"a\": \"\xc3\xa9\"}\0z", 15));
  TEST_ASSERT(contains(inputErrorOf([&] { back.ints("x"); }),
                       "the checkpoint '" + path + "' has no integer dataset 'x'"));
  // Written again: replaced, no temporary left.
  cp.setInts("n", {5});
  cp.write(path);
  TEST_EQUALITY(sc::io::CheckpointFile::read(path).ints("n").at(0), 5);
  TEST_EQUALITY(temporaries(dir).size(), 0u);
}

// Integrity (docs/reliability.md "interruption"): every single flipped bit in the bytes of
// every dataset of a checkpoint is refused by read(), with the file named; the intact file reads.
// The datasets' file offsets come from HDF5 (contiguous storage, H5Dget_offset).
TEUCHOS_UNIT_TEST(CheckpointFile, EveryFlippedBitInTheDatasetsIsRefused)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = freshDirectory(*comm, "checkpoint_flips");
  if (comm->getRank() != 0) return;
  const std::string path = dir + "/checkpoint.h5";
  sc::io::CheckpointFile cp;
  cp.setDoubles("mesh_coordinates", {0.0, 1.0, -0.5, 0.25, 1e-3});
  cp.setInts("mesh_generations", {0, 1, 2, 31});
  cp.setString("parameters", "{\"Material\": {\"Young modulus\": 20600}}");
  cp.write(path);
  TEST_NOTHROW(sc::io::CheckpointFile::read(path));
  std::vector<std::pair<std::string, std::pair<haddr_t, hsize_t>>> extents;
  {
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    for (const char* name : {"mesh_coordinates", "mesh_generations", "parameters"}) {
      const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
      extents.push_back({name, {H5Dget_offset(set), H5Dget_storage_size(set)}});
      H5Dclose(set);
    }
    H5Fclose(file);
  }
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  int flips = 0, refused = 0;
  for (const auto& [name, extent] : extents) {
    TEST_ASSERT(extent.first != HADDR_UNDEF && extent.first + extent.second <= bytes.size());
    for (hsize_t i = 0; i < extent.second; ++i)
      for (int bit = 0; bit < 8; ++bit) {
        std::string damaged = bytes;
        damaged[extent.first + i] = static_cast<char>(damaged[extent.first + i] ^ (1 << bit));
        std::ofstream(path, std::ios::binary | std::ios::trunc) << damaged;
        ++flips;
        const std::string e = inputErrorOf([&] { sc::io::CheckpointFile::read(path); });
        if (contains(e, "the checkpoint '" + path + "' fails its integrity check"))
          ++refused;
        else
          out << name << " byte " << i << " bit " << bit << ": " << e << "\n";
      }
  }
  out << refused << " of " << flips << " flips refused\n";
  TEST_EQUALITY(refused, flips);
  TEST_ASSERT(flips >= 8 * (5 * 8 + 4 * 8));
}

TEUCHOS_UNIT_TEST(CheckpointFile, MissingOrForeignFilesAreNamed)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = freshDirectory(*comm, "checkpoint_errors");
  if (comm->getRank() != 0) return;
  TEST_ASSERT(contains(inputErrorOf([&] { sc::io::CheckpointFile::read(dir + "/none.h5"); }),
                       "no checkpoint '" + dir + "/none.h5'"));
  std::ofstream(dir + "/text.h5") << "hello\n";
  TEST_ASSERT(contains(inputErrorOf([&] { sc::io::CheckpointFile::read(dir + "/text.h5"); }),
                       "the checkpoint '" + dir + "/text.h5' cannot be read: not an HDF5 file"));
}

TEUCHOS_UNIT_TEST(OutputDirectory, RestartRemovesTheFilesOfLaterCycles)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = freshDirectory(*comm, "restart_cleanup");
  if (comm->getRank() == 0)
    for (const char* f :
         {"summary.json", "checkpoint.h5", "sol.xdmf", "sol_c0000.h5", "sol_c0002.h5",
          "sol_c0003.h5", "sol_c0012.h5", "contact_cycle2.csv", "contact_cycle3.csv",
          "contact_cycle10.csv", "sol_c0001.h5.tmp.77", "checkpoint.h5.tmp.5", "notes.txt",
          "other_c0009.h5", "history.csv", "history.csv.tmp.8"})
      std::ofstream(dir + "/" + f) << "x";
  comm->barrier();
  const auto removed = sc::io::removeFilesAfterCycle(dir, "sol", 2, *comm);
  TEST_EQUALITY(removed.size(), 7u);
  if (comm->getRank() != 0) return;
  const std::vector<std::string> expected = {
      "checkpoint.h5.tmp.5", "contact_cycle10.csv", "contact_cycle3.csv", "history.csv.tmp.8",
      "sol_c0001.h5.tmp.77", "sol_c0003.h5",        "sol_c0012.h5"};
  TEST_ASSERT(removed == expected);
  for (const char* f : {"summary.json", "checkpoint.h5", "sol.xdmf", "sol_c0000.h5", "sol_c0002.h5",
                        "contact_cycle2.csv", "notes.txt", "other_c0009.h5", "history.csv"})
    TEST_ASSERT(std::filesystem::exists(dir + "/" + f));
}

}  // namespace
