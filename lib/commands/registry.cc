// The list of CLI commands. Each factory is defined in its own <name>_command.cc.
#include "commands/registry.h"

namespace gearfem::commands
{
  Command profile_command();
  Command dynamics_command();
  Command rate_command();
  Command mesh_command();
  Command bench_command();
  Command solve_command();
  Command condense_command();
  Command helical_command();
  Command system_command();
  Command calibrate_command();
  Command batch_command();
  Command gearbox_command();
  Command optimise_command();
  Command tolerance_command();
  Command export_command();

  const std::vector<Command> &registry()
  {
    static const std::vector<Command> commands = {
      profile_command(),
      dynamics_command(),
      rate_command(),
      gearbox_command(),
      mesh_command(),
      solve_command(),
      condense_command(),
      helical_command(),
      system_command(),
      calibrate_command(),
      batch_command(),
      optimise_command(),
      tolerance_command(),
      export_command(),
      bench_command(),
    };
    return commands;
  }
} // namespace gearfem::commands
