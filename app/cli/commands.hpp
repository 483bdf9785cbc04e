// Subcommands that live in their own files (each returns the process exit status and throws
// UsageError / SceneError / ... for run_cli to report as one line).
#pragma once

namespace trirast {

// trirast fuzz: app/cli/cmd_fuzz.cpp
int cmd_fuzz(int argc, char** argv);

// trirast sweep and trirast fit: app/cli/cmd_sweep.cpp
int cmd_sweep(int argc, char** argv);
int cmd_fit(int argc, char** argv);

}  // namespace trirast
