/* hj_ls_accuracy.c -- the toolbox's accuracy levels; see hj_ls_accuracy.h. */
#include "hj_ls_accuracy.h"

#include <string.h>

#include "hj_ls_deriv.h"

static const struct {
    const char *name;
    int scheme, order;
} level[HJ_LS_NACC] = {
    {"low", HJ_LS_UPWIND_FIRST, 1},
    {"medium", HJ_LS_ENO2, 2},
    {"high", HJ_LS_ENO3A, 3},
    {"veryHigh", HJ_LS_WENO5A, 3},
};

const char *hj_ls_accuracy_name(int acc) { return acc >= 0 && acc < HJ_LS_NACC ? level[acc].name : "?"; }
int hj_ls_accuracy_scheme(int acc) { return level[acc].scheme; }
int hj_ls_accuracy_order(int acc) { return level[acc].order; }

int hj_ls_accuracy_parse(const char *s, int *acc, hj_error *err)
{
    for (int k = 0; k < HJ_LS_NACC; k++)
        if (!strcmp(s, level[k].name)) {
            *acc = k;
            return HJ_OK;
        }
    return hj_error_set(err, HJ_EINVAL, "unknown accuracy '%s' (low, medium, high, veryHigh)", s);
}
