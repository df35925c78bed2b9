#include "apps/cli/commands.h"

#include "apps/bed/bed_command.h"
#include "apps/compare/compare_command.h"
#include "apps/contact/contact_command.h"
#include "apps/crystal/crystal_command.h"
#include "apps/database/database_command.h"
#include "apps/die/die_command.h"
#include "apps/die/jamming_command.h"
#include "apps/docs/docs_command.h"
#include "apps/mcdem/calibrate_command.h"
#include "apps/mcdem/mcdem_command.h"
#include "apps/rve/rve_command.h"
#include "apps/tablet/tablet_command.h"

namespace compax::cli
{
  std::vector<std::unique_ptr<Command>>
  all_commands()
  {
    std::vector<std::unique_ptr<Command>> commands;
    commands.push_back(make_contact_command());
    commands.push_back(make_die_command());
    commands.push_back(make_jamming_command());
    commands.push_back(make_crystal_command());
    commands.push_back(make_mcdem_command());
    commands.push_back(make_calibrate_command());
    commands.push_back(make_tablet_command());
    commands.push_back(make_rve_command());
    commands.push_back(make_database_command());
    commands.push_back(make_bed_command());
    commands.push_back(make_compare_command());
    commands.push_back(make_docs_command());
    return commands;
  }
} // namespace compax::cli
