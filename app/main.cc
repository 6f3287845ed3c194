// gearfem: finite-element spur-gear contact analysis. The executable only dispatches;
// every command lives in lib/commands.
#include "commands/registry.h"

int main(int argc, char **argv)
{
  return gearfem::commands::main(argc, argv);
}
