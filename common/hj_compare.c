#include "hj_compare.h"

#include <math.h>
#include <string.h>

static const char *kind_names[] = {"error", "order", "count", "ratio", "value", "bound", "exact"};
static const char *verdict_names[] = {"match", "close", "differs", "missing", "ambiguous"};

hj_kind hj_kind_from_name(const char *name)
{
    for (int k = 0; k < HJ_KIND_UNKNOWN; k++)
        if (strcmp(name, kind_names[k]) == 0) return (hj_kind)k;
    return HJ_KIND_UNKNOWN;
}

const char *hj_kind_name(hj_kind k) { return k < HJ_KIND_UNKNOWN ? kind_names[k] : "unknown"; }

const char *hj_verdict_name(hj_verdict v) { return (unsigned)v <= HJ_AMBIGUOUS ? verdict_names[v] : "?"; }

int hj_verdict_from_name(const char *name)
{
    for (int v = 0; v <= HJ_AMBIGUOUS; v++)
        if (strcmp(name, verdict_names[v]) == 0) return v;
    return -1;
}

/* Largest of c/p and p/c, for same-signed nonzero values. */
static double factor(double p, double c)
{
    if (p == c) return 1.0;
    if (p == 0 || c == 0 || (p < 0) != (c < 0)) return INFINITY;
    double r = c / p;
    return r >= 1 ? r : 1 / r;
}

static hj_verdict by_factor(double p, double c, double match_rel, double close_factor)
{
    if (p == c) return HJ_MATCH;
    /* 1e-12: a value exactly on a boundary (44 against 40) is inside */
    if (p != 0 && fabs(c / p - 1) <= match_rel + 1e-12) return HJ_MATCH;
    if (factor(p, c) <= close_factor + 1e-12) return HJ_CLOSE;
    return HJ_DIFFERS;
}

hj_verdict hj_compare(hj_kind kind, double p, double c, int *roundoff)
{
    if (roundoff) *roundoff = 0;
    if (!isfinite(c)) return HJ_DIFFERS;
    switch (kind) {
    case HJ_KIND_ERROR:
        if (fabs(p) <= HJ_ROUNDOFF_FLOOR && fabs(c) <= HJ_ROUNDOFF_FLOOR) {
            if (roundoff) *roundoff = 1;
            return HJ_MATCH;
        }
        return by_factor(p, c, 0.05, 2.0);
    case HJ_KIND_ORDER: {
        double d = fabs(c - p);
        return d <= 0.1 + 1e-12 ? HJ_MATCH : d <= 0.5 + 1e-12 ? HJ_CLOSE : HJ_DIFFERS;
    }
    case HJ_KIND_COUNT: return by_factor(p, c, 0.10, 1.5);
    case HJ_KIND_RATIO: return by_factor(p, c, 0.25, 2.0);
    case HJ_KIND_VALUE: return by_factor(p, c, 0.01, 1.1);
    case HJ_KIND_BOUND: return c <= p ? HJ_MATCH : c <= 10 * p ? HJ_CLOSE : HJ_DIFFERS;
    case HJ_KIND_EXACT: return c == p ? HJ_MATCH : p != 0 && fabs(c / p - 1) <= 0.01 + 1e-12 ? HJ_CLOSE : HJ_DIFFERS;
    default: return HJ_DIFFERS;
    }
}

double hj_difference(hj_kind kind, double p, double c)
{
    switch (kind) {
    case HJ_KIND_ORDER:
    case HJ_KIND_VALUE: return c - p;
    case HJ_KIND_BOUND: return p != 0 ? c / p : c - p;
    default: return p != 0 ? c / p : NAN;
    }
}

void hj_compare_rules(FILE *out)
{
    fprintf(out,
            "- **error** (L1, L-infinity, ...): *match* when |computed/published - 1| <= 5 %%, "
            "*close* within a factor 2. When both values are <= %.0e they are both at round-off "
            "level for O(1) data and their ratio carries no information: *match (round-off)*.\n"
            "- **order** (pairwise log2 ratios, fitted slopes): *match* when |computed - published| <= 0.1, "
            "*close* when <= 0.5.\n"
            "- **count** (iterations): *match* within 10 %%, *close* within a factor 1.5.\n"
            "- **ratio** (CPU-time or memory ratios): *match* within 25 %%, *close* within a factor 2. "
            "Shown, but never a reason for `make check` to fail: they depend on the machine and its load.\n"
            "- **value** (other checked numbers): *match* within 1 %%, *close* within 10 %%.\n"
            "- **bound** (differences from a reference that is exact up to its own rounding): the reference cell is the "
            "largest difference allowed; *match* at or below it, *close* within 10 times it.\n"
            "- **exact** (step counts that must agree): *match* when equal, *close* within 1 %%.\n"
            "- *ambiguous*: the published cell cannot be read unambiguously in the source; shown, never compared. "
            "*missing*: no computed value.\n",
            HJ_ROUNDOFF_FLOOR);
}
