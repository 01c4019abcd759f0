// spifit: identification of sheet-metal material parameters for SPIF.
// Exit codes: 0 ok, 1 failure (numerical), 2 usage or input error (one line on stderr); a run
// ended by SIGINT or SIGTERM: 128 + the signal (130, 143; docs/reference/file-formats.md, "Run status").
#include "cli/commands.hpp"
#include "cli/mpi_session.hpp"
#include "forward/io/input_error.hpp"
#include "cli/run_signals.hpp"
#include "forward/runtime/omp_wait_policy.hpp"

#include <glog/logging.h>

#include <iostream>
#include <memory>
#include <omp.h>

namespace {

// "unknown subcommand foo (subcommands: ...)" when the command that needs a subcommand (spifit,
// spifit material) was given a word that is none of its subcommands; "" otherwise. CLI11 says
// only "A subcommand is required" then.
std::string unknown_subcommand(const CLI::App& app) {
  const CLI::App* a = &app;
  while (!a->get_subcommands().empty()) a = a->get_subcommands().front();
  if (a->get_require_subcommand_min() == 0) return "";
  for (const std::string& word : app.remaining(true)) {
    if (word.empty() || word[0] == '-') continue;
    std::string names;
    for (const CLI::App* s : a->get_subcommands([](const CLI::App*) { return true; }))
      if (!s->get_group().empty()) names += (names.empty() ? "" : ", ") + s->get_name();  // hidden ones (job) not
    const std::string command = a == &app ? "" : a->get_name() + " ";
    return "unknown " + command + "subcommand " + word + " (subcommands: " + names + ")";
  }
  return "";
}

// --threads: a whole number from 0 to kMaxThreads. CLI::NonNegativeNumber printed its range up
// to the largest double (300 digits) and let 1000 through. 512 is the hardware threads of the
// largest two-socket servers (2 x 128 cores x 2 SMT): no machine is refused its own thread count,
// while more threads than the hardware has only slow the OpenMP loops down (results do not depend
// on the count, docs/reference/cli.md).
constexpr int kMaxThreads = 512;
const CLI::Validator kThreads(
    [](std::string& text) -> std::string {
      const std::string why = "must be a whole number from 0 (OpenMP's default) to " + std::to_string(kMaxThreads) + ", got '" + text + "'";
      if (text.empty() || text.size() > 5 || text.find_first_not_of("0123456789") != std::string::npos) return why;
      return std::stoi(text) <= kMaxThreads ? "" : why;
    },
    "0.." + std::to_string(kMaxThreads));

// The subcommand named on the command line ("" if none): the first word that is no option nor
// the value of --threads.
std::string subcommand_of(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--threads") {
      ++i;
      continue;
    }
    if (!a.empty() && a[0] != '-') return a;
  }
  return "";
}

}  // namespace

// Ceres logs through glog, which without initialisation starts its first message with "Logging
// before InitGoogleLogging()" and writes log files under /tmp once initialised. spifit says in
// its own words what a user needs: glog goes to stderr only, and only for fatal errors (with
// --verbose also warnings and errors: the optimiser's own remarks).
namespace {
void quiet_glog(const char* program) {
  FLAGS_logtostderr = true;
  FLAGS_minloglevel = google::GLOG_FATAL;
  google::InitGoogleLogging(program);
}
}  // namespace

int main(int argc, char** argv) {
  spifit::runtime::ensure_passive_omp_wait(argv);
  quiet_glog(argv[0]);
  spifit::cli::start_signal_thread();  // before any other thread (OpenMP, Ceres) exists
  std::unique_ptr<spifit::cli::mpi::Session> mpi;
  try {
    // A job's process (started by a worker rank, with the rank's environment) is no rank.
    if (subcommand_of(argc, argv) != "job") mpi = std::make_unique<spifit::cli::mpi::Session>(&argc, &argv);
  } catch (const std::exception& e) {
    std::cerr << "spifit: " << e.what() << "\n";
    return 2;
  }
  if (spifit::cli::mpi::size() > 1) {
    const std::string command = subcommand_of(argc, argv);
    if (command != "fit" && command != "sweep") {
      if (!spifit::cli::mpi::is_worker())
        std::cerr << "spifit: " << (command.empty() ? std::string("this command") : "spifit " + command)
                  << " runs in one process: under mpirun only fit and sweep spread their runs over the ranks\n";
      return 2;
    }
  }
  CLI::App app{"spifit " SPIFIT_VERSION " - material parameter identification for Single Point Incremental Forming"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("spifit ") + SPIFIT_VERSION);
  spifit::cli::GlobalOptions g;
  app.add_option("--threads", g.threads, "OpenMP threads (0: default)")->check(kThreads);
  app.add_flag("-q,--quiet", g.quiet, "print nothing but errors");
  app.add_flag("-v,--verbose", g.verbose, "print more detail");
  int exit_code = 0;
  spifit::cli::add_lankford_command(app, g, exit_code);
  spifit::cli::add_material_command(app, g, exit_code);
  spifit::cli::add_run_command(app, g, exit_code);
  spifit::cli::add_check_sensitivities_command(app, g, exit_code);
  spifit::cli::add_fit_command(app, g, exit_code);
  spifit::cli::add_sweep_command(app, g, exit_code);
  spifit::cli::add_report_command(app, g, exit_code);
  spifit::cli::add_status_command(app, g, exit_code);
  spifit::cli::add_job_command(app, g, exit_code);
  spifit::cli::add_scan_command(app, g, exit_code);
  spifit::cli::add_inputs_command(app, g, exit_code);
  std::string command_line = "spifit";
  for (int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];
  spifit::cli::add_synth_command(app, g, exit_code, command_line);
  app.parse_complete_callback([&] {
    if (g.threads > 0) omp_set_num_threads(g.threads);
    if (g.verbose) FLAGS_minloglevel = google::GLOG_WARNING;
  });
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    const std::string unknown = unknown_subcommand(app);
    std::cerr << "spifit: " << spifit::io::one_line(unknown.empty() ? e.what() : unknown) << " (see --help)\n";
    return 2;
  } catch (const spifit::io::InputError& e) {
    std::cerr << "spifit: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "spifit: error: " << spifit::io::one_line(e.what()) << "\n";
    return 1;
  }
  return exit_code;
}
