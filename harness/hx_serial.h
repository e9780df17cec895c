/**
 * @file hx_serial.h
 * @brief Serial ports for `harness live` and `harness stream`, through
 *        libserialport (8 data bits, no parity, 1 stop bit, no flow control).
 *
 * A path that is a symbolic link (e.g. /dev/serial/by-id/usb-...) is
 * resolved first: libserialport looks a port up by its /dev name in sysfs.
 *
 * Testing without hardware: libserialport 0.1.1 refuses a pseudo-terminal
 * (no sysfs node for /dev/pts/N; no modem-control lines, so TIOCMGET fails
 * with ENOTTY). The CLI test (tests/cli/test_live.sh) therefore preloads
 * tests/cli/pty_seam.c into the unmodified harness: it answers only those two
 * questions (the sysfs lookup of /sys/class/tty/pts/N and the four TIOCM*
 * requests on a pty) and lets every other call reach libserialport and the
 * kernel. The code below is the same with and without the seam.
 */
#ifndef HX_SERIAL_H
#define HX_SERIAL_H

#include <signal.h>
#include <stddef.h>

typedef struct hx_serial hx_serial_t;

/** Open mode. */
enum { HX_SERIAL_READ = 1, HX_SERIAL_WRITE = 2 };

/** Result of a read: bytes (> 0), a timeout (0), or the port is gone. */
#define HX_SERIAL_GONE (-1L)

/**
 * Open a serial port.
 * @param path   device (symbolic links are resolved)
 * @param baud   baud rate (e.g. 460800)
 * @param mode   HX_SERIAL_READ, HX_SERIAL_WRITE or both
 * @param err    receives a one-line message on failure
 * @return the port, or NULL
 */
hx_serial_t *hx_serial_open(const char *path, int baud, int mode, char *err, size_t err_size);

/** Read what is available, waiting up to timeout_ms for the first byte.
 *  @return bytes read (> 0), 0 on timeout, HX_SERIAL_GONE when the port
 *  has hung up or disappeared (message in hx_serial_error()). */
long hx_serial_read(hx_serial_t *s, void *buf, size_t size, unsigned timeout_ms);

/** Write all n bytes, giving up when the port takes no byte for timeout_ms,
 *  or when *stop (a signal handler's flag; NULL: none) is set: libserialport
 *  resumes a write a signal interrupts, so the wait is cut into 100 ms
 *  slices and the flag looked at between them.
 *  @return 0; 1 stopped by *stop (the bytes before were written); -1 on a
 *  timeout or a vanished port (hx_serial_error()). */
int hx_serial_write(hx_serial_t *s, const void *buf, size_t n, unsigned timeout_ms, const volatile sig_atomic_t *stop);

/** Wait until everything written has left the port. 0 or -1. */
int hx_serial_drain(hx_serial_t *s);

/** The resolved device path. */
const char *hx_serial_path(const hx_serial_t *s);

/** The last error, one line. */
const char *hx_serial_error(const hx_serial_t *s);

void hx_serial_close(hx_serial_t *s);

#endif /* HX_SERIAL_H */
