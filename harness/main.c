/* ./harness: the Linux reference tool of footnav. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "footnav/fnav_version.h"

#include "hx_cli.h"
#include "hx_commands.h"

typedef struct {
    const char *name;
    int (*fn)(int argc, char **argv);
    const char *summary;
} command_t;

static const command_t k_commands[] = {
    { "info", hx_cmd_info, "rate, duration, gaps, duplicates, saturation, gravity at rest of a log" },
    { "convert", hx_cmd_convert, "convert between .bin, CSV and every importable format" },
    { "merge", hx_cmd_merge, "merge an accelerometer's and a gyroscope's files into one log" },
    { "replay", hx_cmd_replay, "run a log through the navigation filter: trajectory, summary, plot" },
    { "eval", hx_cmd_eval, "run every data set with ground truth and write docs/results.md" },
    { "allan", hx_cmd_allan, "streaming Allan deviation and AR(1) bias-model identification" },
    { "psd", hx_cmd_psd, "streaming Welch PSD and the lowest usable sampling frequency" },
    { "sim", hx_cmd_sim, "simulate foot motion and sensor errors into a log with truth" },
    { "montecarlo", hx_cmd_montecarlo, "run many simulated walks through the filter: error growth, NEES" },
    { "simgap", hx_cmd_simgap, "locate and explain the gap between a real log and its simulated twin" },
    { "simgap-validate", hx_cmd_simgap_validate, "validate simgap on cases with withheld effects" },
    { "live", hx_cmd_live, "navigate live from a serial port, recording to .bin" },
    { "stream", hx_cmd_stream, "play a log out over a serial port in the wire protocol" },
};

static void usage(FILE *f)
{
    size_t i;
    fprintf(f, "usage: harness COMMAND [ARGS...]   (harness COMMAND --help for details)\n"
               "       harness --version           (footnav's version; or -V)\n\ncommands:\n");
    for (i = 0; i < sizeof k_commands / sizeof k_commands[0]; i++) {
        fprintf(f, "  %-16s %s\n", k_commands[i].name, k_commands[i].summary);
    }
}

/* Results printed to standard output count as an output: a full disk or a
 * closed pipe is a write error (exit 3), not a success with the results
 * lost (`info LOG > /dev/full` exited 0) nor a silent death by SIGPIPE
 * before the other outputs were written (`replay LOG --out - --json S |
 * head -1` would lose S). `who` is "info", or NULL for the
 * harness's own usage. */
static int flush_stdout(const char *who, int rc)
{
    errno = 0;
    if ((fflush(stdout) != 0 || ferror(stdout)) && (rc == HX_EXIT_OK || rc == HX_EXIT_DATA)) {
        fprintf(stderr, "harness%s%s: error: cannot write standard output%s%s\n", who != NULL ? " " : "",
                who != NULL ? who : "", errno != 0 ? ": " : "", errno != 0 ? strerror(errno) : "");
        rc = HX_EXIT_IO;
    }
    return rc;
}

static const command_t *find_command(const char *name)
{
    size_t i;
    for (i = 0; i < sizeof k_commands / sizeof k_commands[0]; i++) {
        if (strcmp(name, k_commands[i].name) == 0) {
            return &k_commands[i];
        }
    }
    return NULL;
}

int main(int argc, char **argv)
{
    const command_t *c;
    /* GSL's default error handler aborts the process: a domain error on
     * degenerate data must come back as a NaN or an error code that the
     * command checks and reports (exit 1), never as SIGABRT */
    gsl_set_error_handler_off();
    signal(SIGPIPE, SIG_IGN); /* a closed pipe is a write error (below), as in live and stream */
    /* a file-size limit (ulimit -f) reached is a write error too (EFBIG,
     * exit 3 naming the file): SIGXFSZ killed the process without a word,
     * its other outputs not written */
    signal(SIGXFSZ, SIG_IGN);
    if (argc < 2) {
        usage(stderr);
        return HX_EXIT_USAGE;
    }
    /* `harness --version` (nothing reported a version before: an unknown
     * command, exit 2) */
    if (strcmp(argv[1], "--version") == 0 || strcmp(argv[1], "-V") == 0) {
        if (argc > 2) {
            fprintf(stderr, "harness: error: %s takes no argument\n", argv[1]);
            usage(stderr);
            return HX_EXIT_USAGE;
        }
        printf("harness (footnav) %s\n", FNAV_VERSION_STRING);
        return flush_stdout(NULL, HX_EXIT_OK);
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
        static char help_opt[] = "--help";
        char *help_argv[] = { help_opt, NULL };
        /* `help help` (`help --help`, `--help help`) is the general help,
         * as `help` alone, not "unknown command 'help'", exit 2 */
        if (argc == 2 || (argc == 3 && (strcmp(argv[2], "help") == 0 || strcmp(argv[2], "--help") == 0 ||
                                        strcmp(argv[2], "-h") == 0))) {
            usage(stdout);
            return flush_stdout(NULL, HX_EXIT_OK);
        }
        /* `harness help CMD` is `harness CMD --help` (it printed the list of
         * commands, and `harness help nosuch` exited 0) */
        c = argc == 3 ? find_command(argv[2]) : NULL;
        if (c != NULL) {
            return flush_stdout(c->name, c->fn(1, help_argv));
        }
        if (argc == 3) {
            fprintf(stderr, "harness: error: unknown command '%s'\n", argv[2]);
        } else {
            fprintf(stderr, "harness: error: %s takes one command, not %d\n", argv[1], argc - 2);
        }
        usage(stderr);
        return HX_EXIT_USAGE;
    }
    c = find_command(argv[1]);
    if (c == NULL) {
        fprintf(stderr, "harness: error: unknown command '%s'\n", argv[1]);
        usage(stderr);
        return HX_EXIT_USAGE;
    }
    hx_cmd_name = c->name;
    if (hx_json_stdout_claim(c->name, argc - 2, argv + 2) != 0) {
        return HX_EXIT_USAGE;
    }
    {
        int rc = c->fn(argc - 2, argv + 2);
        if (rc == HX_EXIT_DATA) {
            (void)hx_json_failure(c->name, argc - 2, argv + 2);
        }
        return flush_stdout(c->name, rc);
    }
}
