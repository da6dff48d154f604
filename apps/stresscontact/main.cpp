// stresscontact: the XML-driven application (docs/user-guide.md).
//
//   stresscontact [INPUT.xml] [--output DIR] [--set Path/To/Key=value ...] [--check] [--quiet]
//   stresscontact [INPUT.xml] --restart DIR [--set ...]    (continue a killed adaptive run)
//   stresscontact --print-parameters | --help | --version
//
// Without INPUT it runs the default Hertz 2D deck (input/hertz2d.xml). The whole parameter list
// is validated before any work; a bad deck exits with status 1 and writes nothing.
//
// Exit status: 0 success, 1 bad input (deck, mesh file, command line), 2 a solver did not
// converge (summary.json says converged: false), 3 any other error.
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <Kokkos_Core.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_GlobalMPISession.hpp>
#include <mpi.h>

#include <sc/core/Collective.hpp>
#include <sc/core/Error.hpp>
#include <sc/core/FloatingPointTraps.hpp>
#include <sc/io/MpiIoEnvironment.hpp>

#include "DeckParameters.hpp"
#include "Simulation.hpp"

namespace {

const char* kUsage = R"(Usage:
  stresscontact [INPUT.xml] [options]     run the deck (default: the Hertz 2D deck hertz2d.xml)
  stresscontact --print-parameters        every valid key with its type, default and documentation
  stresscontact --help | --version

Options:
  --output DIR              output directory (overrides Output/Directory)
  --set Path/To/Key=value   override one parameter, e.g. --set "Material/Poisson ratio=0.4999";
                            may be repeated; the value's type is the key's type
  --restart DIR             continue the run whose output directory is DIR from its last complete
                            cycle (DIR/checkpoint.h5, written after every cycle); give the same
                            deck and --set options as that run; the output goes on in DIR
  --check                   validate the deck and the scene (mesh, boundary names), write nothing
  --quiet                   no progress lines

Outputs (in the output directory): summary.json, solution.xdmf + solution_c<N>.h5, and with
contact contact_cycle<N>.csv; checkpoint.h5 for --restart. Exit status: 0 success, 1 bad input, 2 no convergence, 3 other.
)";

struct CommandLine {
  std::string input;
  std::string output;
  std::string restart;
  std::vector<std::string> overrides;
  bool check = false, quiet = false, printParameters = false, help = false, version = false;
};

/// The command line's options (`-h` is a short form of `--help`).
const std::vector<std::string> kOptions = {"--output", "--set",    "--restart",
                                           "--check",  "--quiet",  "--print-parameters",
                                           "--help",   "--version"};

CommandLine parseCommandLine(int argc, char* argv[])
{
  CommandLine cl;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const std::string& flag) -> std::string {
      SC_THROW_IF(i + 1 >= argc, sc::core::InputError, flag << " needs a value. " << kUsage);
      // `--output --check deck.xml` (a value forgotten) would otherwise write into a directory
      // named "--check" and run instead of checking.
      const std::string next = argv[i + 1];
      SC_THROW_IF(next == "-h" || std::count(kOptions.begin(), kOptions.end(), next) > 0,
                  sc::core::InputError,
                  flag << " needs a value, but the next argument is the option '" << next
                       << "' (a value that starts like an option: write it as ./" << next
                       << " or give the value first). " << kUsage);
      return argv[++i];
    };
    // An empty directory (`--output "$DIR"` with DIR unset) is a scripting error: read as "not
    // given", the run would write into the deck's Output/Directory, or --restart would start a
    // fresh run, without a word.
    auto directory = [&](const std::string& flag, const char* withoutIt) -> std::string {
      std::string d = value(flag);
      SC_THROW_IF(d.empty(), sc::core::InputError,
                  flag << " '' is an empty directory name: give a directory (e.g. " << flag
                       << " out), or omit " << flag << " " << withoutIt << ".");
      return d;
    };
    if (a == "--help" || a == "-h")
      cl.help = true;  // handled in main, before Kokkos is initialised
    else if (a == "--version")
      cl.version = true;
    else if (a == "--print-parameters")
      cl.printParameters = true;
    else if (a == "--check")
      cl.check = true;
    else if (a == "--quiet")
      cl.quiet = true;
    else if (a == "--output")
      cl.output = directory(a, "to use the deck's Output/Directory");
    else if (a == "--set")
      cl.overrides.push_back(value(a));
    else if (a == "--restart")
      cl.restart = directory(a, "for a new run");
    else if (a.rfind("--", 0) == 0) {
      std::ostringstream valid;
      for (std::size_t k = 0; k < kOptions.size(); ++k)
        valid << (k ? ", " : "") << kOptions[k];
      SC_THROW_IF(true, sc::core::InputError,
                  "unknown option '" << a << "'. Valid options: " << valid.str() << ".");
    } else {
      SC_THROW_IF(!cl.input.empty(), sc::core::InputError,
                  "more than one input deck given ('" << cl.input << "' and '" << a << "').");
      cl.input = a;
    }
  }
  // --restart DIR writes on in DIR: it is the output directory.
  if (!cl.restart.empty()) {
    SC_THROW_IF(
        !cl.output.empty() && cl.output != cl.restart, sc::core::InputError,
        "--restart " << cl.restart << " continues the run in '" << cl.restart
                     << "', but --output gives '" << cl.output
                     << "': leave --output out (a restarted run writes on in its directory).");
    cl.output = cl.restart;
  }
  return cl;
}

void printFramed(std::ostream& os, const std::string& title, const std::string& message, int rank)
{
  const std::string rule(78, '-');
  os << "\n" << rule << "\nstresscontact: " << title;
  if (rank > 0) os << " (rank " << rank << ")";
  os << "\n" << rule << "\n" << message << "\n" << rule << std::endl;
}

// How long a failing rank waits for the others to report an error too before it concludes the
// error is its own and aborts the job (docs/reliability.md).
constexpr double kErrorAgreementSeconds = 30.0;

}  // namespace

// The rank of this process as the MPI launcher announces it (Open MPI, MPICH/Hydra, Slurm), 0
// when started without one: lets the commands that need no MPI answer once, before MPI_Init.
int launcherRank()
{
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK", "SLURM_PROCID"})
    if (const char* v = std::getenv(name)) return std::atoi(v);
  return 0;
}

// Whether an MPI launcher (mpiexec/mpirun, Hydra, Slurm's srun) started this process.
bool startedByLauncher()
{
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_PROCID"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

// A process started without a launcher is an MPI singleton: one rank, no peers. Open MPI 4.1's
// defaults make its MPI_Init take 0.35 s on this project's machine, about half of a small run:
// it forks an `orted` daemon (which only MPI_Comm_spawn would need) and initialises UCX, the
// network transport, for a job that never sends a message to another process. The environment
// below (read by MPI_Init) starts the singleton without the daemon and with the shared-memory/self
// transports, which takes 0.03 s (docs/performance.md "Start-up"). Nothing changes under a
// launcher, and a value the user set (environment or an Open MPI parameter file read as the
// same variable) is left alone.
void startSingletonWithoutDaemonOrNetwork()
{
#ifdef OPEN_MPI
  if (startedByLauncher()) return;
  ::setenv("OMPI_MCA_ess_singleton_isolated", "1", /*overwrite=*/0);
  ::setenv("OMPI_MCA_pml", "ob1", 0);
  ::setenv("OMPI_MCA_btl", "self,vader", 0);
#endif
}

int main(int argc, char* argv[])
{
  // --help, --version and --print-parameters need neither MPI nor Kokkos: they answer before
  // either starts (MPI's start-up alone took 0.36 s of the 0.7 s that `--help` took).
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h" || a == "--version" || a == "--print-parameters") {
      if (launcherRank() != 0) return 0;
      if (a == "--version")
        std::cout << "stresscontact " << sc::app::versionString() << std::endl;
      else if (a == "--print-parameters")
        sc::app::printValidParameters(std::cout);
      else
        std::cout << kUsage;
      return 0;
    }
  }
  // Before MPI_Init: keeps Open MPI from an MPI-IO component that overflows a buffer on paths
  // over 244 characters (sc/io/MpiIoEnvironment.hpp).
  sc::io::leaveOutOverflowingMpiIoComponents();
  startSingletonWithoutDaemonOrNetwork();
  Teuchos::GlobalMPISession mpiSession(&argc, &argv, nullptr);
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank();
  Kokkos::ScopeGuard kokkos(argc, argv);
  sc::core::enableFloatingPointTrapsFromEnvironment();  // SC_TRAP_FPE=1: set by CTest
  sc::core::ErrorAgreement errors(*comm);
  int code = 0;
  std::string title, message;
  try {
    const CommandLine cl = parseCommandLine(argc, argv);
    if (cl.version) {
      if (rank == 0) std::cout << "stresscontact " << sc::app::versionString() << std::endl;
      return 0;
    }
    if (cl.printParameters) {
      if (rank == 0) sc::app::printValidParameters(std::cout);
      return 0;
    }
    const std::string deck = cl.input.empty() ? sc::app::defaultDeckPath() : cl.input;
    auto params = sc::app::readAndValidateDeck(deck, cl.overrides, cl.output);
    sc::app::Simulation simulation(comm, params, deck, cl.quiet);
    if (!cl.restart.empty()) simulation.restartFrom(cl.restart);
    if (cl.check) {
      simulation.checkScene();
      if (rank == 0) std::cout << "stresscontact: '" << deck << "' is valid." << std::endl;
      return 0;
    }
    simulation.run();
    return 0;
  } catch (const sc::core::InputError& e) {
    code = 1, title = "input error", message = e.what();
  } catch (const sc::core::ConvergenceError& e) {
    // Simulation::run has already marked summary.json converged: false on rank 0.
    code = 2, title = "no convergence", message = e.what();
  } catch (const std::exception& e) {
    code = 3, title = "error", message = e.what();
  }
  // Every rank that gets here failed. Input is the same on every rank and the library's checks
  // are collective, so normally all ranks fail together: then rank 0 alone prints the error and
  // all ranks leave normally (MPI_Finalize) with the documented exit status. An error of one
  // rank only (the others did not report one in time) aborts the job rather than hang it.
  const int agreed = errors.agree(code, kErrorAgreementSeconds);
  if (agreed != 0) {
    if (rank == 0) printFramed(std::cerr, title, message, 0);
    return agreed;
  }
  printFramed(std::cerr, title, message, rank);
  MPI_Abort(MPI_COMM_WORLD, code);
  return code;
}
