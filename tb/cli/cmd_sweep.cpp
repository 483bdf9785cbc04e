// trirast sweep / fit (issue 6): placeholders until the sweep lands.
#include "cli/args.hpp"
#include "cli/commands.hpp"

namespace trirast {

int cmd_sweep(int, char**) { throw UsageError("trirast sweep: not built yet"); }
int cmd_fit(int, char**) { throw UsageError("trirast fit: not built yet"); }

}  // namespace trirast
