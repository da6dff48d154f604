// Shared main() for the Teuchos unit tests of every package: MPI and Kokkos set-up, then the
// standard Teuchos unit-test command line (--help lists filters such as --test=NAME).
#include <Kokkos_Core.hpp>
#include <Teuchos_GlobalMPISession.hpp>
#include <Teuchos_UnitTestRepository.hpp>

int main(int argc, char* argv[])
{
  Teuchos::GlobalMPISession mpiSession(&argc, &argv, nullptr);
  Kokkos::ScopeGuard kokkos(argc, argv);
  return Teuchos::UnitTestRepository::runUnitTestsFromMain(argc, argv);
}
