#pragma once
// Subcommands of the spifit executable. The CLI only parses options and calls the libraries.
#include <CLI/CLI.hpp>

namespace spifit::cli {

struct GlobalOptions {
  int threads = 0;  // 0: OpenMP default
  bool quiet = false;
  bool verbose = false;
};

// Each registers a subcommand; its callback sets the process exit code through `exit_code`.
void add_lankford_command(CLI::App& app, const GlobalOptions& g, int& exit_code);
void add_material_command(CLI::App& app, const GlobalOptions& g, int& exit_code);
void add_run_command(CLI::App& app, const GlobalOptions& g, int& exit_code);
void add_fit_command(CLI::App& app, const GlobalOptions& g, int& exit_code);
void add_sweep_command(CLI::App& app, const GlobalOptions& g, int& exit_code);
void add_report_command(CLI::App& app, const GlobalOptions& g, int& exit_code);
void add_inputs_command(CLI::App& app, const GlobalOptions& g, int& exit_code);
// `spifit check-sensitivities SCENE --sensitivities P,...`: exact against central differences.
void add_check_sensitivities_command(CLI::App& app, const GlobalOptions& g, int& exit_code);
// `spifit status DIR` (status_command.cpp).
void add_status_command(CLI::App& app, const GlobalOptions& g, int& exit_code);
void add_job_command(CLI::App& app, const GlobalOptions& g, int& exit_code);
void add_scan_command(CLI::App& app, const GlobalOptions& g, int& exit_code);
void add_synth_command(CLI::App& app, const GlobalOptions& g, int& exit_code, const std::string& command_line);

}  // namespace spifit::cli
