/* Shared helper of the fuzz targets: the readers take a path, so each input
 * is written to a per-process file in /dev/shm (tmpfs) first. */
#ifndef FUZZ_SUPPORT_H
#define FUZZ_SUPPORT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <unistd.h>

static const char *fuzz_write_input(const uint8_t *data, size_t size, const char *suffix)
{
    static char path[128];
    FILE *f;
    snprintf(path, sizeof path, "/dev/shm/fnav_fuzz_%d%s", (int)getpid(), suffix);
    f = fopen(path, "wb");
    if (f == NULL) {
        return NULL;
    }
    if (size > 0 && fwrite(data, 1, size, f) != size) {
        fclose(f);
        return NULL;
    }
    fclose(f);
    return path;
}

#endif
