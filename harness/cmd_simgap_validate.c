/* harness simgap-validate: the sim-to-real gap diagnosis on simulated cases
 * whose effect is withheld, scored afterwards (docs/simgap.md,
 * docs/simgap-validation.md). */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hx_cli.h"
#include "hx_commands.h"
#include "hx_simgap_valid.h"

static const hx_opt_t k_opts[] = {
    { "--cases", "N", "number of cases (default 40): controls and each effect in turn", 0 },
    { "--seed", "S",
      "seed of the case generator (default 1); case i owns the seeds S + 20000 i ... S + 20000 i + 19999 "
      "(mod 2^32): its diagnosis draws from S + 20000 i ... + 12009, its log's noise is S + 20000 i + 12010; "
      "two runs share nothing when their seeds are at least 20000 x --cases apart",
      0 },
    { "--duration", "S", "length of the static cases (default 3600: the catalogue's reference)", 0 },
    { "--rate", "HZ", "rate of the static cases (default 200)", 0 },
    { "--walk-duration", "S", "length of the walk cases (default 60)", 0 },
    { "--walk-rate", "HZ", "rate of the walk cases (default 200)", 0 },
    { "--static-only", NULL, "static-domain and timing cases only", 0 },
    { "--walk-only", NULL, "motion-domain (walk) cases only", 0 },
    { "--seeds", "N", "twins per model in the diagnosis (default 16)", 0 },
    { "--mag-range", "LO,HI", "magnitudes as multiples of the detectable threshold (default 1,10; 0.001 <= LO <= HI <= 1000)", 0 },
    { "--json", "FILE", "every case and its score as JSON ('-': standard output, the text then on standard error)", 0 },
    { "--markdown", "FILE", "the summary as Markdown (docs/simgap-validation.md)", 0 },
    { "--verbose", NULL, "print the diagnosis of every case", 0 },
    { "--effects", "LIST", "draw only these effects (comma-separated names; control for controls)", 0 },
    { "--only", "K", "run only case K (same draw as in the full run; for inspection)", 0 },
    { "--quiet", NULL, "no line per case", 0 },
    { NULL, NULL, NULL, 0 }
};

static const hx_spec_t k_spec = {
    "simgap-validate", "[options]",
    "Validate the sim-to-real gap diagnosis on cases whose effect is withheld:\n"
    "each case is a log simulated with one effect of the catalogue drawn at\n"
    "random (or none: a control) at a magnitude drawn log-uniformly from the\n"
    "range the catalogue documents as detectable; the diagnosis sees only the\n"
    "log. Prints a line per case, the confusion matrix, top-1 identification\n"
    "rate (the top-ranked effect is the withheld one), location (Jaccard index\n"
    "of the channels the diagnosis flags against the effect's: 1 = exactly its\n"
    "channels), parameter error (relative, on the right effect), held-out gap\n"
    "shrink and the targets of issue 6 (docs/simgap.md, \"Validation\").",
    0, 0, k_opts
};

int hx_cmd_simgap_validate(int argc, char **argv)
{
    int rc;
    hx_args_t a;
    sgv_opts_t o = sgv_opts_default();
    sgv_case_t *cases;
    char err[HX_ERR_SIZE], why[HX_ERR_SIZE];
    long n = o.cases, seeds = o.seeds;
    double seed = (double)o.seed;
    const char *json, *md, *mr;
    double t0;
    int status = HX_EXIT_OK;
    int pr = hx_args_parse(&k_spec, argc, argv, &a);
    if (pr != 0) {
        return pr > 0 ? HX_EXIT_OK : HX_EXIT_USAGE;
    }
    {
        static const char *const k_file_only[] = { "--markdown", NULL };
        if (hx_refuse_dash("simgap-validate", &a, k_file_only) != 0) {
            return HX_EXIT_USAGE;
        }
    }
    if (hx_arg_long(&a, "--cases", 1, 100000, &n) != 0 || hx_arg_whole(&a, "--seed", 0.0, 4294967295.0, &seed) != 0 ||
        hx_arg_double(&a, "--duration", 10.0, 1e6, &o.duration_s) != 0 ||
        hx_arg_double(&a, "--rate", 10.0, 1e5, &o.rate_hz) != 0 ||
        hx_arg_double(&a, "--walk-duration", 20.0, 3600.0, &o.walk_duration_s) != 0 ||
        hx_arg_double(&a, "--walk-rate", 50.0, 5000.0, &o.walk_rate_hz) != 0 ||
        hx_arg_long(&a, "--seeds", 3, SG_MAX_TWINS, &seeds) != 0) {
        return HX_EXIT_USAGE;
    }
    mr = hx_arg(&a, "--mag-range");
    if (mr != NULL) {
        /* two numbers and nothing else (sscanf took "1,10x" and "1,inf") */
        const char *e1 = mr;
        if (hx_scan_number(mr, &e1, &o.mag_lo) != 0 || *e1 != ',' || hx_parse_number(e1 + 1, &o.mag_hi) != 0 ||
            !(o.mag_lo >= SGV_MAG_MIN) || !(o.mag_hi >= o.mag_lo) || !(o.mag_hi <= SGV_MAG_MAX)) {
            hx_error("simgap-validate", "--mag-range '%s': wants LO,HI with %g <= LO <= HI <= %g", mr, SGV_MAG_MIN,
                     SGV_MAG_MAX);
            return HX_EXIT_USAGE;
        }
    }
    if (hx_flag(&a, "--static-only") && hx_flag(&a, "--walk-only")) {
        hx_error("simgap-validate", "--static-only and --walk-only exclude each other");
        return HX_EXIT_USAGE;
    }
    o.walks = !hx_flag(&a, "--static-only");
    o.statics = !hx_flag(&a, "--walk-only");
    if (o.statics && seeds < 4) {
        /* a static case's held-out tests leave one twin out of each null:
         * with 3 twins no effect could be accepted (as simgap refuses) */
        hx_error("simgap-validate", "--seeds %ld is too few for static cases: the held-out tests of an effect need "
                                    "at least 4 twins (or --walk-only)", seeds);
        return HX_EXIT_USAGE;
    }
    o.cases = (int)n;
    o.seed = (uint32_t)seed; /* [0, 4294967295], as sim's */
    o.seeds = (int)seeds;
    o.verbose = hx_flag(&a, "--verbose");
    o.effects = hx_arg(&a, "--effects");
    {
        long only = -1;
        if (hx_arg_long(&a, "--only", 0, 100000, &only) != 0) {
            return HX_EXIT_USAGE;
        }
        o.only = (int)only;
    }
    if (sgv_check_opts(&o, err, sizeof err) != 0) {
        hx_error("simgap-validate", "%s", err);
        return HX_EXIT_USAGE;
    }
    o.quiet = hx_flag(&a, "--quiet");
    json = hx_arg(&a, "--json");
    md = hx_arg(&a, "--markdown");
    {
        /* one file for both: the Markdown replaced the JSON, exit 0 */
        static const char *const outs[] = { "--json", "--markdown", NULL };
        if (hx_output_is_input("simgap-validate", NULL, &a, outs)) {
            return HX_EXIT_USAGE;
        }
    }
    /* a run takes minutes: an output that cannot be written is said now */
    if ((json != NULL && hx_check_writable("simgap-validate", json) != 0) ||
        (md != NULL && hx_check_writable("simgap-validate", md) != 0)) {
        return HX_EXIT_IO;
    }
    cases = (sgv_case_t *)calloc((size_t)n, sizeof *cases);
    if (cases == NULL) {
        hx_error("simgap-validate", "out of memory");
        return HX_EXIT_IO;
    }
    /* Ctrl-C or SIGTERM: the run stops before its next case and reports
     * the cases it ran (a full run takes 13 minutes; they were lost) */
    hx_stop_on_signals("simgap-validate", "after the current case");
    o.stop = &hx_stop_sig;
    t0 = hx_now_s();
    rc = sgv_run(&o, cases, o.quiet ? NULL : stdout, err, sizeof err);
    t0 = hx_now_s() - t0;
    why[0] = '\0';
    if (rc < 0) {
        /* the cases before the failure are reported and written below */
        hx_error("simgap-validate", "%s; the report covers the cases run before it", err);
        snprintf(why, sizeof why, "%s", err);
        status = HX_EXIT_IO;
    } else if (rc > 0) {
        hx_warn("simgap-validate", "interrupted: the report covers the cases run before the signal");
        snprintf(why, sizeof why, "interrupted by %s: the report covers the cases run before the signal",
                 hx_stop_sig == SIGTERM ? "SIGTERM" : "SIGINT");
        status = 128 + (int)hx_stop_sig; /* as the shell reports a command a signal ended */
    }
    sgv_report(stdout, &o, cases, (int)n, 0, t0);
    if (json != NULL && sgv_write_json(json, &o, cases, (int)n, t0, why[0] != '\0' ? why : NULL) != 0) {
        status = HX_EXIT_IO;
    }
    if (md != NULL) {
        FILE *f = fopen(md, "w");
        if (f == NULL) {
            hx_error("simgap-validate", "cannot write %s (%s)", md, strerror(errno));
            status = HX_EXIT_IO;
        } else {
            int failed;
            errno = 0;
            sgv_report(f, &o, cases, (int)n, 1, t0);
            failed = ferror(f) != 0;
            if (fclose(f) != 0 || failed) {
                /* the report's write failed (a full disk): said, not exit 3 alone */
                hx_error("simgap-validate", "%s: write failed (%s)", md, strerror(errno != 0 ? errno : EIO));
                status = HX_EXIT_IO;
            }
        }
    }
    free(cases);
    return status;
}
