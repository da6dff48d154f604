// Shared main() for the Teuchos unit tests of every package: MPI set-up, then the standard
// Teuchos unit-test command line (--help lists filters such as --test=NAME).
#include <Teuchos_GlobalMPISession.hpp>
#include <Teuchos_UnitTestRepository.hpp>

int main(int argc, char* argv[])
{
  Teuchos::GlobalMPISession mpiSession(&argc, &argv, nullptr);
  return Teuchos::UnitTestRepository::runUnitTestsFromMain(argc, argv);
}
