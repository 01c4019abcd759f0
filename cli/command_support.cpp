#include "cli/command_support.hpp"

#include "cli/mpi_session.hpp"

#include <iostream>

namespace spifit::cli {

std::vector<std::string> job_args(const GlobalOptions& g, std::vector<std::string> command) {
  std::vector<std::string> args{"-q"};
  if (g.threads > 0) args.insert(args.end(), {"--threads", std::to_string(g.threads)});
  args.insert(args.end(), command.begin(), command.end());
  return args;
}

void note_on_stderr(const std::string& why) { std::cerr << "spifit: rank " << mpi::rank() << ": " << why << "\n"; }

}  // namespace spifit::cli
