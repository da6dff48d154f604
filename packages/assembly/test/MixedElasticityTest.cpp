// Verification of the assembled mixed elasticity system (docs/verification.md), run at 1, 2 and 4
// ranks:
// - patch test (docs/theory.md §"Mixed formulation"): the linear stress field of
// core::LinearPatchSolution lies in RT_k
//   for k ≥ 1, so σ_h = σ, θ_h = θ and div σ_h = div σ up to round-off on the unstructured Gmsh
//   meshes of the half disc / unit cube (u_h is its L² projection; analytic argument in
//   docs/verification.md). This is the test that catches orientation and Piola mistakes.
// - rank independence: the same problem solved on this communicator and on each rank alone
//   (MPI_COMM_SELF) gives the same errors to 1e-10 relative, for KLU2 and MUMPS.
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <sc/testing/ElasticityTestProblem.hpp>

using sc::test::solveVerification;
using sc::test::VerificationSetup;

namespace {

void patchTest(const VerificationSetup& s, Teuchos::FancyOStream& out, bool& success)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto r = solveVerification(s, comm).back();
  out << s.source << " k=" << s.degree << " dofs=" << r.dofs
      << ": |σ−σh|/|σ| = " << r.errors.stress / r.errors.stressNorm
      << ", |div(σ−σh)| = " << r.errors.stressDiv
      << ", |θ−θh|/|θ| = " << r.errors.rotation / r.errors.rotationNorm << "\n";
  TEST_COMPARE(r.errors.stress, <=, 1e-9 * r.errors.stressNorm);
  TEST_COMPARE(r.errors.stressDiv, <=, 1e-9 * r.errors.stressDivNorm);
  TEST_COMPARE(r.errors.rotation, <=, 1e-9 * r.errors.rotationNorm);
}

}  // namespace

TEUCHOS_UNIT_TEST(MixedElasticity, PatchTest2D)
{
  for (int k : {1, 2}) {
    VerificationSetup s;
    s.source = "Unit square";
    s.meshSize = 0.3;
    s.degree = k;
    s.exact = "Linear patch";
    patchTest(s, out, success);
  }
}

TEUCHOS_UNIT_TEST(MixedElasticity, PatchTest3D)
{
  VerificationSetup s;
  s.source = "Unit cube";
  s.dim = 3;
  s.meshSize = 0.5;
  s.degree = 1;
  s.exact = "Linear patch";
  patchTest(s, out, success);
}

TEUCHOS_UNIT_TEST(MixedElasticity, SameErrorsOnAnyRankCount)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::RCP<const Teuchos::Comm<int>> self = Teuchos::rcp(new Teuchos::SerialComm<int>());
  for (const std::string solver : {"KLU2", "MUMPS"}) {
    VerificationSetup s;
    s.meshSize = 0.25;
    s.nu = 0.4999;
    s.solver = solver;
    const auto all = solveVerification(s, comm).back().errors;
    VerificationSetup serial = s;
    serial.solver = "KLU2";
    const auto one = solveVerification(serial, self).back().errors;
    out << solver << " on " << comm->getSize() << " ranks: |σ−σh| = " << all.stress
        << " (1 rank KLU2: " << one.stress << ")\n";
    TEST_FLOATING_EQUALITY(all.stress, one.stress, 1e-10);
    TEST_FLOATING_EQUALITY(all.stressDiv, one.stressDiv, 1e-10);
    TEST_FLOATING_EQUALITY(all.displacement, one.displacement, 1e-10);
    TEST_FLOATING_EQUALITY(all.rotation, one.rotation, 1e-10);
  }
}
