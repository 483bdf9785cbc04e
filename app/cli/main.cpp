#include "cli/cli.hpp"

int main(int argc, char** argv) { return trirast::run_cli(argc, argv); }
