/* fuzz_map.h -- what both map targets do with a map they have read: what
 * eikonal does next (interpolate at (fx mx, fy my), invert the values)
 * when the read succeeded, else check that its message is one clean line. */
#ifndef FUZZ_MAP_H
#define FUZZ_MAP_H

#include <stdlib.h>

#include "fuzz_file.h"
#include "hj_map.h"

static inline void fuzz_map_use(int rc, hj_map *m, hj_error *err, double fx, double fy)
{
    if (rc == HJ_OK) {
        (void)hj_map_eval(fx * m->mx, fy * m->my, m);
        (void)hj_map_invert(m, err);
        hj_map_free(m);
    } else if (!fuzz_message_ok(err->msg)) {
        abort();
    }
}

#endif
