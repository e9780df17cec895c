/* Fuzz target: the sensor profile file reader. */
#include <stdint.h>

#include "fuzz_support.h"
#include "hx_profile.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char err[320];
    fnav_profile_t p;
    const char *path = fuzz_write_input(data, size, ".profile");
    if (path == NULL) {
        return 0;
    }
    if (hx_profile_read(path, &p, err, sizeof err) == 0) {
        (void)fnav_profile_validate(&p);
    }
    unlink(path);
    return 0;
}
