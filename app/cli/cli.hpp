// The trirast command-line program: subcommands raster, compare, scenes, engines.
#pragma once

namespace trirast {

// Runs the CLI; returns the process exit status (0 ok, 1 engines disagree, 2 bad input or usage).
int run_cli(int argc, char** argv);

}  // namespace trirast
