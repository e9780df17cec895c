/* Serial ports through libserialport (see hx_serial.h). */
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <limits.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <libserialport.h>

#include "hx_serial.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

struct hx_serial {
    struct sp_port *port;
    int fd;
    char path[PATH_MAX];
    char err[512];
};

static void set_err(hx_serial_t *s, const char *what)
{
    char *m = sp_last_error_message();
    snprintf(s->err, sizeof s->err, "%.300s: %s: %.150s", s->path, what, (m != NULL && m[0] != '\0') ? m : "failed");
    if (m != NULL) {
        sp_free_error_message(m);
    }
}

hx_serial_t *hx_serial_open(const char *path, int baud, int mode, char *err, size_t err_size)
{
    hx_serial_t *s = calloc(1, sizeof *s);
    enum sp_mode spm = (enum sp_mode)0;
    if (s == NULL) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    s->fd = -1;
    if (realpath(path, s->path) == NULL) {
        snprintf(err, err_size, "%s: %s", path, strerror(errno));
        free(s);
        return NULL;
    }
    if (sp_get_port_by_name(s->path, &s->port) != SP_OK) {
        /* what the port is, by the name the user gave (and the device it
         * leads to): libserialport's own message is the errno of its sysfs
         * lookup, "No such file or directory" for /dev/null or a pty that
         * exists, and says no word of a pty's seam */
        struct stat st;
        const char *base = strrchr(s->path, '/');
        char name[PATH_MAX + 8];
        if (strcmp(path, s->path) != 0) {
            snprintf(name, sizeof name, "%.2000s (%.2000s)", path, s->path);
        } else {
            snprintf(name, sizeof name, "%.4000s", path);
        }
        if (stat(s->path, &st) == 0 && !S_ISCHR(st.st_mode)) {
            snprintf(err, err_size, "%.500s: not a serial port (not a character device)", name);
        } else if (strncmp(s->path, "/dev/pts/", 9) == 0) {
            snprintf(err, err_size,
                     "%.500s: a pseudo-terminal, which libserialport refuses (no /sys/class/tty entry, no modem "
                     "lines); for a desk test preload tests/cli/pty_seam.c (docs/wire-protocol.md, \"Testing "
                     "without a sensor\")",
                     name);
        } else {
            snprintf(err, err_size, "%.500s: not a serial port libserialport knows (no /sys/class/tty/%.100s entry)",
                     name, base != NULL ? base + 1 : s->path);
        }
        free(s);
        return NULL;
    }
    if (mode & HX_SERIAL_READ) {
        spm = (enum sp_mode)(spm | SP_MODE_READ);
    }
    if (mode & HX_SERIAL_WRITE) {
        spm = (enum sp_mode)(spm | SP_MODE_WRITE);
    }
    if (sp_open(s->port, spm) != SP_OK) {
        set_err(s, "cannot open");
        goto fail;
    }
    if (sp_set_baudrate(s->port, baud) != SP_OK || sp_set_bits(s->port, 8) != SP_OK ||
        sp_set_parity(s->port, SP_PARITY_NONE) != SP_OK || sp_set_stopbits(s->port, 1) != SP_OK ||
        sp_set_flowcontrol(s->port, SP_FLOWCONTROL_NONE) != SP_OK) {
        set_err(s, "cannot configure 8N1 without flow control at the requested baud rate");
        sp_close(s->port);
        goto fail;
    }
    if (sp_get_port_handle(s->port, &s->fd) != SP_OK) {
        s->fd = -1;
    }
    return s;
fail:
    snprintf(err, err_size, "%s", s->err);
    sp_free_port(s->port);
    free(s);
    return NULL;
}

/* After a quiet period: has the port hung up or vanished? A pty whose other
 * end closed reports POLLHUP; an unplugged USB adapter also loses its node.
 * A tty hung up under a node that stays (a Bluetooth rfcomm link, a
 * vhangup) reports POLLHUP with POLLIN, and its reads return 0 at once:
 * with nothing left to read, that is a hang-up too (else live would loop
 * on it at full speed).
 * The "nothing left" test (FIONREAD) changes nothing on a port opened by
 * path, as checked on Linux: on a tty hung up (vhangup, the pty master
 * closed, a USB or rfcomm hang-up) FIONREAD fails with EIO and the kernel
 * has discarded the pending bytes (reads return 0); only a pty master whose
 * slave closed reports POLLHUP with POLLIN and bytes still readable, and
 * that cannot be opened by name. Mutants of it survive every test for that
 * reason; it stays for a driver that reports POLLHUP before hanging up. */
static int gone(hx_serial_t *s)
{
    if (s->fd >= 0) {
        struct pollfd p;
        int avail = 0;
        p.fd = s->fd;
        p.events = POLLIN;
        p.revents = 0;
        if (poll(&p, 1, 0) > 0 && (p.revents & (POLLHUP | POLLERR | POLLNVAL)) &&
            (!(p.revents & POLLIN) || ioctl(s->fd, FIONREAD, &avail) != 0 || avail == 0)) {
            snprintf(s->err, sizeof s->err, "%.300s: the port hung up (the other end closed or the device went away)",
                     s->path);
            return 1;
        }
    }
    if (access(s->path, F_OK) != 0) {
        snprintf(s->err, sizeof s->err, "%.300s: the device disappeared", s->path);
        return 1;
    }
    return 0;
}

long hx_serial_read(hx_serial_t *s, void *buf, size_t size, unsigned timeout_ms)
{
    enum sp_return r = sp_blocking_read_next(s->port, buf, size, timeout_ms);
    if (r > 0) {
        return (long)r;
    }
    if (r < 0) {
        set_err(s, "read failed (port gone?)");
        return HX_SERIAL_GONE;
    }
    return gone(s) ? HX_SERIAL_GONE : 0L;
}

int hx_serial_write(hx_serial_t *s, const void *buf, size_t n, unsigned timeout_ms, const volatile sig_atomic_t *stop)
{
    const unsigned char *p = (const unsigned char *)buf;
    size_t off = 0;
    unsigned idle_ms = 0;
    while (off < n) {
        /* a slice, not the whole timeout: a write blocked on a port nobody
         * reads would hold off Ctrl-C until the 10 s timeout */
        const unsigned slice = timeout_ms - idle_ms < 100u ? timeout_ms - idle_ms : 100u;
        enum sp_return r;
        if (stop != NULL && *stop) {
            return 1;
        }
        r = sp_blocking_write(s->port, p + off, n - off, slice);
        if (r < 0) {
            set_err(s, "write failed (port gone?)");
            return -1;
        }
        if (r > 0) {
            off += (size_t)r;
            idle_ms = 0;
        } else {
            idle_ms += slice;
            if (idle_ms >= timeout_ms) {
                snprintf(s->err, sizeof s->err,
                         "%.300s: the port took no data for %u ms (%zu of %zu bytes sent; nobody reading?)", s->path,
                         timeout_ms, off, n);
                return -1;
            }
        }
    }
    return 0;
}

int hx_serial_drain(hx_serial_t *s)
{
    if (sp_drain(s->port) != SP_OK) {
        set_err(s, "drain failed");
        return -1;
    }
    return 0;
}

const char *hx_serial_path(const hx_serial_t *s)
{
    return s->path;
}

const char *hx_serial_error(const hx_serial_t *s)
{
    return s->err;
}

void hx_serial_close(hx_serial_t *s)
{
    if (s == NULL) {
        return;
    }
    sp_close(s->port);
    sp_free_port(s->port);
    free(s);
}
