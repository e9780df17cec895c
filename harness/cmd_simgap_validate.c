/* harness simgap-validate: placeholder until the sim-to-real gap issue (#6) lands. */
#include <stdio.h>
#include <string.h>

#include "hx_cli.h"
#include "hx_commands.h"

int hx_cmd_simgap_validate(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "harness simgap-validate: not available yet (planned in issue #6, sim-to-real gap)\n");
    return HX_EXIT_UNAVAIL;
}
