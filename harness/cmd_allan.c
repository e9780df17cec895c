/* harness allan: placeholder until the sensor analysis issue (#4) lands. */
#include <stdio.h>
#include <string.h>

#include "hx_cli.h"
#include "hx_commands.h"

int hx_cmd_allan(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "harness allan: not available yet (planned in issue #4, sensor analysis)\n");
    return HX_EXIT_UNAVAIL;
}
