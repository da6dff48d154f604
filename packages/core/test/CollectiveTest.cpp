// The collective layer (core/Collective.hpp) at 1, 2 and 4 ranks: reductions and broadcasts
// against the values each rank's contribution gives by hand (rank r contributes r + 1, so the
// sum is n(n + 1)/2, the maximum n and the minimum 1), and the error agreement: the same
// exception type and message on every rank, and the exit status agreed or found to be one
// rank's.
#include <stdexcept>
#include <string>
#include <vector>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include "sc/core/Collective.hpp"
#include "sc/core/Error.hpp"

namespace {

using sc::core::Comm;

Teuchos::RCP<const Comm> world() { return Teuchos::DefaultComm<int>::getComm(); }

// The message of the sc::core exception `f` throws, with its type (empty if none).
template <class F>
std::pair<std::string, std::string> thrown(F f)
{
  try {
    f();
  } catch (const sc::core::InputError& e) {
    return {"InputError", e.what()};
  } catch (const sc::core::InternalError& e) {
    return {"InternalError", e.what()};
  } catch (const sc::core::ConvergenceError& e) {
    return {"ConvergenceError", e.what()};
  } catch (const sc::core::Error& e) {
    return {"Error", e.what()};
  }
  return {"", ""};
}

}  // namespace

TEUCHOS_UNIT_TEST(Collective, SumsMaximaMinima)
{
  const auto comm = world();
  const int n = comm->getSize(), r = comm->getRank();
  TEST_EQUALITY(sc::core::sumOverRanks(*comm, r + 1), n * (n + 1) / 2);
  TEST_EQUALITY(sc::core::sumOverRanks(*comm, 1LL << 40), n * (1LL << 40));  // beyond int
  TEST_EQUALITY(sc::core::sumOverRanks(*comm, 0.5 * (r + 1)), 0.25 * n * (n + 1));
  TEST_EQUALITY(sc::core::maxOverRanks(*comm, r + 1), n);
  TEST_EQUALITY(sc::core::maxOverRanks(*comm, -1.5 * (r + 1)), -1.5);
  TEST_EQUALITY(sc::core::maxOverRanks(*comm, static_cast<long long>(r)), n - 1LL);
  TEST_EQUALITY(sc::core::minOverRanks(*comm, r + 1), 1);
  TEST_EQUALITY(sc::core::minOverRanks(*comm, -1.5 * (r + 1)), -1.5 * n);
  TEST_EQUALITY(sc::core::minOverRanks(*comm, static_cast<long long>(r)), 0LL);

  // Element-wise: entry i of rank r is (i + 1)(r + 1).
  const double local[3] = {1.0 * (r + 1), 2.0 * (r + 1), 3.0 * (r + 1)};
  double sum[3], max[3], min[3];
  sc::core::sumOverRanks(*comm, 3, local, sum);
  sc::core::maxOverRanks(*comm, 3, local, max);
  sc::core::minOverRanks(*comm, 3, local, min);
  for (int i = 0; i < 3; ++i) {
    TEST_EQUALITY(sum[i], (i + 1) * 0.5 * n * (n + 1));
    TEST_EQUALITY(max[i], (i + 1.0) * n);
    TEST_EQUALITY(min[i], i + 1.0);
  }
  const std::vector<long long> counts = sc::core::sumOverRanks(*comm, std::vector<long long>{1, r});
  TEST_EQUALITY(counts[0], static_cast<long long>(n));
  TEST_EQUALITY(counts[1], n * (n - 1LL) / 2);
  TEST_EQUALITY(sc::core::sumOverRanks(*comm, std::vector<double>{}).size(), 0u);
}

TEUCHOS_UNIT_TEST(Collective, GatherConcatenatesInRankOrder)
{
  const auto comm = world();
  const int n = comm->getSize(), r = comm->getRank();
  // Rank r holds r entries 100 r + j (rank 0 none): lengths differ, one rank gives nothing.
  std::vector<double> mine;
  for (int j = 0; j < r; ++j)
    mine.push_back(100.0 * r + j);
  const std::vector<double> all = sc::core::gatherAllConcatenated(*comm, mine);
  std::vector<double> expected;
  for (int q = 0; q < n; ++q)
    for (int j = 0; j < q; ++j)
      expected.push_back(100.0 * q + j);
  TEST_COMPARE_ARRAYS(all, expected);
}

TEUCHOS_UNIT_TEST(Collective, BroadcastsFromAnyRank)
{
  const auto comm = world();
  const int n = comm->getSize(), r = comm->getRank();
  const int root = n - 1;
  // Every rank starts with a value of its own length; the root's replaces them all.
  std::string s(static_cast<std::size_t>(r + 2), 'a' + static_cast<char>(r));
  s[0] = '\0';  // an embedded NUL is kept
  sc::core::broadcast(*comm, root, s);
  std::string expected(static_cast<std::size_t>(root + 2), 'a' + static_cast<char>(root));
  expected[0] = '\0';
  TEST_EQUALITY(s, expected);
  std::vector<double> v(static_cast<std::size_t>(3 * r), 1.0 * r);
  sc::core::broadcast(*comm, root, v);
  TEST_COMPARE_ARRAYS(v, std::vector<double>(static_cast<std::size_t>(3 * root), 1.0 * root));
  std::vector<int> empty(static_cast<std::size_t>(r), r);
  sc::core::broadcast(*comm, 0, empty);  // rank 0's is empty
  TEST_EQUALITY(empty.size(), 0u);
  int i = r;
  long l = -r;
  long long ll = (1LL << 40) + r;
  double d = 0.25 * r;
  sc::core::broadcast(*comm, root, i);
  sc::core::broadcast(*comm, root, l);
  sc::core::broadcast(*comm, root, ll);
  sc::core::broadcast(*comm, root, d);
  TEST_EQUALITY(i, root);
  TEST_EQUALITY(l, -static_cast<long>(root));
  TEST_EQUALITY(ll, (1LL << 40) + root);
  TEST_EQUALITY(d, 0.25 * root);
}

TEUCHOS_UNIT_TEST(Collective, RunOnRootThrowsTheSameErrorOnEveryRank)
{
  const auto comm = world();
  int ran = 0;
  sc::core::runOnRoot(*comm, [&] { ran = 1; });
  TEST_EQUALITY(sc::core::sumOverRanks(*comm, ran), 1);  // rank 0 only

  using Result = std::pair<std::string, std::string>;
  TEST_EQUALITY(
      thrown([&] { sc::core::runOnRoot(*comm, [] { throw sc::core::InputError("bad deck"); }); }),
      Result("InputError", "bad deck"));
  TEST_EQUALITY(
      thrown([&] { sc::core::runOnRoot(*comm, [] { throw sc::core::ConvergenceError("no"); }); }),
      Result("ConvergenceError", "no"));
  TEST_EQUALITY(
      thrown([&] { sc::core::runOnRoot(*comm, [] { throw sc::core::InternalError("bug"); }); }),
      Result("InternalError", "bug"));
  // Anything else becomes an Error (of no more specific type).
  TEST_EQUALITY(
      thrown([&] { sc::core::runOnRoot(*comm, [] { throw std::runtime_error("disk full"); }); }),
      Result("Error", "disk full"));
}

TEUCHOS_UNIT_TEST(Collective, LowestFailingRanksMessageOnEveryRank)
{
  const auto comm = world();
  const int n = comm->getSize(), r = comm->getRank();
  sc::core::throwIfAnyRankFailed(*comm, "");  // nobody failed: returns
  // The last ranks fail (at 1 rank: rank 0), with messages of different lengths.
  const int firstFailing = n / 2;
  const std::string mine = r >= firstFailing ? "check " + std::string(r + 1, 'x') + " failed" : "";
  using Result = std::pair<std::string, std::string>;
  const std::string text = "check " + std::string(firstFailing + 1, 'x') + " failed";
  const std::string expected = n > 1 ? "rank " + std::to_string(firstFailing) + ": " + text : text;
  TEST_EQUALITY(thrown([&] { sc::core::throwIfAnyRankFailed(*comm, mine); }),
                Result("InputError", expected));
  TEST_EQUALITY(thrown([&] { sc::core::throwIfAnyRankFailed(*comm, mine, true); }),
                Result("InternalError", expected));
}

TEUCHOS_UNIT_TEST(Collective, ErrorAgreementOnTheExitStatus)
{
  const auto comm = world();
  const int n = comm->getSize(), r = comm->getRank();
  {
    // Every rank fails, with statuses 1..n: all agree on the largest.
    sc::core::ErrorAgreement agreement(*comm);
    TEST_EQUALITY(agreement.agree(r + 1, 30.0), n);
  }
  if (n == 1) return;
  {
    // Ranks 1.. fail while rank 0 does not report within 0.2 s: each finds the error its own
    // (0). Rank 0 reports later (after the barrier), and sees their status 7; the agreement of
    // the others completes then, in their destructor.
    sc::core::ErrorAgreement agreement(*comm);
    if (r > 0) TEST_EQUALITY(agreement.agree(7, 0.2), 0);
    comm->barrier();
    if (r == 0) TEST_EQUALITY(agreement.agree(1, 30.0), 7);
  }
}
