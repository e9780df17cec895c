/* harness eval: placeholder until the navigation issue (#3) lands. */
#include <stdio.h>
#include <string.h>

#include "hx_cli.h"
#include "hx_commands.h"

int hx_cmd_eval(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "harness eval: not available yet (planned in issue #3, navigation)\n");
    return HX_EXIT_UNAVAIL;
}
