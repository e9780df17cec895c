/* harness montecarlo: placeholder until the simulator issue (#5) lands. */
#include <stdio.h>
#include <string.h>

#include "hx_cli.h"
#include "hx_commands.h"

int hx_cmd_montecarlo(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "harness montecarlo: not available yet (planned in issue #5, simulator)\n");
    return HX_EXIT_UNAVAIL;
}
