// Shared main() for the Teuchos unit tests of every package: MPI and Kokkos set-up, then the
// standard Teuchos unit-test command line (--help lists filters such as --test=NAME).
// Floating-point exceptions trap when SC_TRAP_FPE=1, which CTest sets for every test.
#include <Kokkos_Core.hpp>
#include <Teuchos_GlobalMPISession.hpp>
#include <Teuchos_UnitTestRepository.hpp>

#include <sc/core/FloatingPointTraps.hpp>

int main(int argc, char* argv[])
{
  Teuchos::GlobalMPISession mpiSession(&argc, &argv, nullptr);
  Kokkos::ScopeGuard kokkos(argc, argv);
  sc::core::enableFloatingPointTrapsFromEnvironment();
  return Teuchos::UnitTestRepository::runUnitTestsFromMain(argc, argv);
}
