/* Test seam for running the real libserialport path on a pseudo-terminal.
 *
 * Loaded with LD_PRELOAD into an unmodified bin/harness by
 * tests/cli/test_live.sh (docs/wire-protocol.md, "Testing without a sensor").
 * libserialport 0.1.1 refuses a pty for two reasons, and this file answers
 * exactly those two questions the way a plain serial port would; everything
 * else (open, termios configuration, baud rate, blocking reads and writes,
 * drain, close) is libserialport talking to the pty:
 *
 * 1. sp_get_port_by_name() looks the device up in sysfs: lstat() and
 *    readlink() of /sys/class/tty/<name>. A /dev/pts/N slave has no sysfs
 *    node, so the lookup fails with "Device not found". Here, for paths
 *    /sys/class/tty/pts/N only, lstat() reports a symbolic link and
 *    readlink() returns "../../devices/virtual/tty/ptmx" (the node of the pty
 *    multiplexer): libserialport then describes the port as a native serial
 *    port named "pts/N".
 * 2. sp_open() and the configuration calls read and set the modem-control
 *    lines with ioctl(TIOCMGET / TIOCMSET / TIOCMBIS / TIOCMBIC); a pty has
 *    no modem lines and answers ENOTTY. Here, on a pty slave only (character
 *    device, Unix98 pty major 136..143), those four requests succeed: reads
 *    return DTR|RTS|CTS|DSR|CD asserted, writes are accepted and ignored.
 *
 * Every other call goes to the C library unchanged. The Debian build of
 * libserialport 0.1.1 calls the glibc 2.2.5 compatibility symbol __lxstat
 * for lstat; both that and lstat are interposed. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdarg.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#define PTS_NODE "/sys/class/tty/pts/"
#define PTMX_LINK "../../devices/virtual/tty/ptmx"

int __lxstat(int ver, const char *path, struct stat *st);
int lstat(const char *path, struct stat *st);
ssize_t readlink(const char *path, char *buf, size_t size);
int ioctl(int fd, unsigned long request, ...);

static int is_pts_node(const char *path)
{
    return path != NULL && strncmp(path, PTS_NODE, sizeof PTS_NODE - 1) == 0 && path[sizeof PTS_NODE - 1] != '\0';
}

static int fake_link_stat(struct stat *st)
{
    memset(st, 0, sizeof *st);
    st->st_mode = S_IFLNK | 0777;
    st->st_nlink = 1;
    st->st_size = (off_t)strlen(PTMX_LINK);
    return 0;
}

int __lxstat(int ver, const char *path, struct stat *st)
{
    static int (*real)(int, const char *, struct stat *);
    if (is_pts_node(path)) {
        return fake_link_stat(st);
    }
    if (real == NULL) {
        real = (int (*)(int, const char *, struct stat *))dlvsym(RTLD_NEXT, "__lxstat", "GLIBC_2.2.5");
    }
    if (real == NULL) {
        errno = ENOSYS;
        return -1;
    }
    return real(ver, path, st);
}

int lstat(const char *path, struct stat *st)
{
    static int (*real)(const char *, struct stat *);
    if (is_pts_node(path)) {
        return fake_link_stat(st);
    }
    if (real == NULL) {
        real = (int (*)(const char *, struct stat *))dlsym(RTLD_NEXT, "lstat");
    }
    if (real == NULL) {
        errno = ENOSYS;
        return -1;
    }
    return real(path, st);
}

ssize_t readlink(const char *path, char *buf, size_t size)
{
    static ssize_t (*real)(const char *, char *, size_t);
    if (is_pts_node(path)) {
        size_t n = strlen(PTMX_LINK);
        if (n > size) {
            n = size;
        }
        memcpy(buf, PTMX_LINK, n);
        return (ssize_t)n;
    }
    if (real == NULL) {
        real = (ssize_t(*)(const char *, char *, size_t))dlsym(RTLD_NEXT, "readlink");
    }
    if (real == NULL) {
        errno = ENOSYS;
        return -1;
    }
    return real(path, buf, size);
}

static int is_pty_slave(int fd)
{
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISCHR(st.st_mode)) {
        return 0;
    }
    return major(st.st_rdev) >= 136 && major(st.st_rdev) <= 143;
}

int ioctl(int fd, unsigned long request, ...)
{
    static int (*real)(int, unsigned long, ...);
    va_list ap;
    void *arg;
    va_start(ap, request);
    arg = va_arg(ap, void *);
    va_end(ap);
    if ((request == TIOCMGET || request == TIOCMSET || request == TIOCMBIS || request == TIOCMBIC) &&
        is_pty_slave(fd)) {
        if (request == TIOCMGET && arg != NULL) {
            *(int *)arg = TIOCM_DTR | TIOCM_RTS | TIOCM_CTS | TIOCM_DSR | TIOCM_CD;
        }
        return 0;
    }
    if (real == NULL) {
        real = (int (*)(int, unsigned long, ...))dlsym(RTLD_NEXT, "ioctl");
    }
    if (real == NULL) {
        errno = ENOSYS;
        return -1;
    }
    return real(fd, request, arg);
}
