/* Test seam: a signal that lands inside a write() to the serial port.
 *
 * Loaded with LD_PRELOAD beside tests/cli/pty_seam.c by tests/cli/test_live.sh.
 * A Ctrl-C that arrives while `harness stream` is inside the kernel's write
 * to a tty is a window of microseconds, hit by chance in a CI run; this seam
 * puts the signal there every time. With EINTR_SEAM_AT=N, the Nth write() to
 * a pty slave (counted from 1) raises SIGINT, so the process's handler runs,
 * and then the write does what Linux's tty write does when it finds a signal
 * pending before any byte went (n_tty_write returns -ERESTARTSYS): it is
 * restarted (here, the real write) when the handler was installed with
 * SA_RESTART, and otherwise fails with EINTR, which libserialport's
 * sp_blocking_write reports as "write() failed". Every other write goes to
 * the C library unchanged. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

ssize_t write(int fd, const void *buf, size_t n);

static int is_pty_slave(int fd)
{
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISCHR(st.st_mode)) {
        return 0;
    }
    return major(st.st_rdev) >= 136 && major(st.st_rdev) <= 143;
}

ssize_t write(int fd, const void *buf, size_t n)
{
    static ssize_t (*real)(int, const void *, size_t);
    static long count;
    if (real == NULL) {
        real = (ssize_t(*)(int, const void *, size_t))dlsym(RTLD_NEXT, "write");
    }
    if (real == NULL) {
        errno = ENOSYS;
        return -1;
    }
    if (is_pty_slave(fd)) {
        const char *at = getenv("EINTR_SEAM_AT");
        if (at != NULL && ++count == atol(at)) {
            struct sigaction sa;
            (void)raise(SIGINT);
            if (sigaction(SIGINT, NULL, &sa) == 0 && sa.sa_handler != SIG_DFL && sa.sa_handler != SIG_IGN &&
                !(sa.sa_flags & SA_RESTART)) {
                errno = EINTR;
                return -1;
            }
        }
    }
    return real(fd, buf, n);
}
