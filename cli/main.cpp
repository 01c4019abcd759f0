// spifit: identification of sheet-metal material parameters for SPIF.
// Exit codes: 0 ok, 1 failure (numerical), 2 usage or input error (one line on stderr).
#include "cli/commands.hpp"
#include "forward/io/input_error.hpp"
#include "forward/runtime/omp_wait_policy.hpp"

#include <iostream>
#include <omp.h>

int main(int argc, char** argv) {
  spifit::runtime::ensure_passive_omp_wait(argv);
  CLI::App app{"spifit " SPIFIT_VERSION " - material parameter identification for Single Point Incremental Forming"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("spifit ") + SPIFIT_VERSION);
  spifit::cli::GlobalOptions g;
  app.add_option("--threads", g.threads, "OpenMP threads (0: default)")->check(CLI::NonNegativeNumber);
  app.add_flag("-q,--quiet", g.quiet, "print nothing but errors");
  app.add_flag("-v,--verbose", g.verbose, "print more detail");
  int exit_code = 0;
  spifit::cli::add_lankford_command(app, g, exit_code);
  spifit::cli::add_material_command(app, g, exit_code);
  spifit::cli::add_run_command(app, g, exit_code);
  spifit::cli::add_fit_command(app, g, exit_code);
  spifit::cli::add_sweep_command(app, g, exit_code);
  spifit::cli::add_report_command(app, g, exit_code);
  spifit::cli::add_scan_command(app, g, exit_code);
  spifit::cli::add_inputs_command(app, g, exit_code);
  std::string command_line = "spifit";
  for (int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];
  spifit::cli::add_synth_command(app, g, exit_code, command_line);
  app.parse_complete_callback([&] {
    if (g.threads > 0) omp_set_num_threads(g.threads);
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
    std::cerr << "spifit: " << spifit::io::one_line(e.what()) << " (see --help)\n";
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
