/* hx_serial_write's idle timer on a pseudo-terminal (run by
 * tests/cli/test_live.sh with the LD_PRELOAD seam tests/cli/pty_seam.c, so
 * that libserialport opens the pty slave):
 *
 * 1. slow but steady reader: once the pty's buffers are full, the reader
 *    takes 4 KB every 200 ms, eight times. Each pause is shorter than the
 *    500 ms timeout, the whole (1.6 s) longer: the write must complete,
 *    since the timer restarts whenever a slice of the write made progress
 *    (`harness stream` to a slow link; a mutant that never restarted it
 *    gave up after 500 ms of pauses in all);
 * 2. a reader that reads nothing: the write gives up after the timeout
 *    with "took no data for 500 ms".
 *
 * Exit 0 when both behave, 1 otherwise (the reason on standard output).
 * Usage: serial_write_slow */
#define _XOPEN_SOURCE 600
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "hx_serial.h"

#define CHUNK 4096
#define STEPS 8
#define GAP_MS 200
#define TIMEOUT_MS 500u

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void sleep_ms(long ms)
{
    struct timespec ts;
    ts.tv_sec = ms / 1000;
    ts.tv_nsec = (ms % 1000) * 1000000L;
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR) {
    }
}

/* a new pty master, its slave's name in name */
static int new_pty(char *name, size_t size)
{
    int m = posix_openpt(O_RDWR | O_NOCTTY);
    if (m < 0 || grantpt(m) != 0 || unlockpt(m) != 0 || ptsname(m) == NULL) {
        return -1;
    }
    snprintf(name, size, "%s", ptsname(m));
    return m;
}

/* bytes a pty slave takes before a write would block (a throwaway pair) */
static long pty_capacity(void)
{
    char name[256], buf[1024];
    long cap = 0;
    int m = new_pty(name, sizeof name), s;
    if (m < 0) {
        return -1;
    }
    s = open(name, O_WRONLY | O_NONBLOCK | O_NOCTTY);
    if (s < 0) {
        close(m);
        return -1;
    }
    memset(buf, 0x55, sizeof buf);
    for (;;) {
        ssize_t w = write(s, buf, sizeof buf);
        if (w <= 0) {
            sleep_ms(50); /* the buffers may still move: try once more */
            w = write(s, buf, sizeof buf);
            if (w <= 0) {
                break;
            }
        }
        cap += (long)w;
    }
    close(s);
    close(m);
    return cap;
}

/* read n bytes from fd, CHUNK at a time; steps > 0: the first `steps`
 * chunks each after a pause of GAP_MS */
static int reader(int fd, long n, int steps)
{
    static char buf[CHUNK];
    long got = 0;
    int k;
    for (k = 0; got < n; k++) {
        long want = n - got < CHUNK ? n - got : CHUNK, have = 0;
        if (k < steps) {
            sleep_ms(GAP_MS);
        }
        while (have < want) {
            ssize_t r = read(fd, buf, (size_t)(want - have));
            if (r <= 0) {
                return 1;
            }
            have += (long)r;
        }
        got += have;
    }
    return 0;
}

static int run(int slow, long cap)
{
    char name[256], err[600];
    const long n = cap + (long)STEPS * CHUNK;
    char *data = malloc((size_t)n);
    hx_serial_t *s;
    pid_t pid;
    int m, st = 0, rc;
    double t0, dt;
    if (data == NULL || (m = new_pty(name, sizeof name)) < 0) {
        printf("cannot make a pty\n");
        return 1;
    }
    memset(data, 0x55, (size_t)n);
    s = hx_serial_open(name, 460800, HX_SERIAL_WRITE, err, sizeof err);
    if (s == NULL) {
        printf("cannot open %s: %s\n", name, err);
        return 1;
    }
    pid = fork();
    if (pid == 0) {
        if (slow) {
            _exit(reader(m, n, STEPS));
        }
        pause(); /* reads nothing until killed */
        _exit(0);
    }
    t0 = now_s();
    rc = hx_serial_write(s, data, (size_t)n, TIMEOUT_MS, NULL);
    dt = now_s() - t0;
    if (rc != 0 || !slow) {
        kill(pid, SIGKILL);
    }
    waitpid(pid, &st, 0);
    if (slow) {
        if (rc != 0) {
            printf("slow reader: the write gave up after %.2f s: %s\n", dt, hx_serial_error(s));
            rc = 1;
        } else if (!WIFEXITED(st) || WEXITSTATUS(st) != 0) {
            printf("slow reader: it did not read all %ld bytes\n", n);
            rc = 1;
        } else if (dt < 2.0 * TIMEOUT_MS / 1000.0) {
            printf("slow reader: the write took %.2f s, not more than twice the timeout (a test that tests nothing)\n",
                   dt);
            rc = 1;
        }
    } else if (rc != -1 || strstr(hx_serial_error(s), "took no data for 500 ms") == NULL) {
        printf("silent reader: the write returned %d after %.2f s (%s)\n", rc, dt, hx_serial_error(s));
        rc = 1;
    } else if (dt < TIMEOUT_MS / 1000.0 || dt > 5.0) {
        printf("silent reader: the write gave up after %.2f s, not the 0.5 s timeout\n", dt);
        rc = 1;
    } else {
        rc = 0;
    }
    hx_serial_close(s);
    close(m);
    free(data);
    return rc;
}

int main(void)
{
    long cap = pty_capacity();
    if (cap <= 0) {
        printf("cannot measure a pty's buffer\n");
        return 1;
    }
    return run(1, cap) || run(0, cap);
}
