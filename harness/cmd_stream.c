/* harness stream: placeholder until the firmware and live issue (#7) lands. */
#include <stdio.h>
#include <string.h>

#include "hx_cli.h"
#include "hx_commands.h"

int hx_cmd_stream(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "harness stream: not available yet (planned in issue #7, firmware and live)\n");
    return HX_EXIT_UNAVAIL;
}
