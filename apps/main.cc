#include "apps/cli/application.h"

int
main(int argc, char **argv)
{
  return compax::cli::run_application(argc, argv);
}
