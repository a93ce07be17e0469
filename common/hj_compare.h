/* hj_compare.h -- published value against computed value: the verdict.
 *
 * Every published cell has a kind, and the rule for each kind is written
 * here and only here (hj_compare_rules() prints it for the report):
 *
 *   error  match: |c/p - 1| <= 5 %;  close: within a factor 2.
 *          Round-off: when both values are <= 1e-10 the two are at the
 *          level of accumulated round-off of O(1) data, where their ratio
 *          means nothing; such a cell is a match with reason "round-off".
 *   order  match: |c - p| <= 0.1;    close: |c - p| <= 0.5.
 *   count  match: within 10 %;       close: within a factor 1.5.
 *   ratio  match: within 25 %;       close: within a factor 2
 *          (CPU-time and memory ratios between runs).
 *   value  match: within 1 %;        close: within 10 % (checked numbers
 *          such as areas, radii, times).
 *   bound  match: c <= p;            close: c <= 10 p (p is the largest
 *          difference a reference allows, e.g. its own rounding).
 *   exact  match: c == p;            close: within 1 % (step counts).
 *
 * Verdicts are ordered: match < close < differs < missing.  "ambiguous"
 * marks a published cell that could not be read in the source; it is shown
 * but never compared and never fails.
 */
#ifndef HJ_COMPARE_H
#define HJ_COMPARE_H

#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    HJ_KIND_ERROR,
    HJ_KIND_ORDER,
    HJ_KIND_COUNT,
    HJ_KIND_RATIO,
    HJ_KIND_VALUE,
    HJ_KIND_BOUND,
    HJ_KIND_EXACT,
    HJ_KIND_UNKNOWN
} hj_kind;

typedef enum {
    HJ_MATCH = 0,
    HJ_CLOSE = 1,
    HJ_DIFFERS = 2,
    HJ_MISSING = 3,
    HJ_AMBIGUOUS = 4
} hj_verdict;

/* Below this, both errors count as round-off (see above). */
#define HJ_ROUNDOFF_FLOOR 1e-10

hj_kind hj_kind_from_name(const char *name);
const char *hj_kind_name(hj_kind k);
const char *hj_verdict_name(hj_verdict v);
/* Parse "match", "close", ...; returns -1 if unknown. */
int hj_verdict_from_name(const char *name);

/* Verdict for computed c against published p of the given kind; *roundoff
 * is set when the round-off rule decided. Non-finite c is "differs". */
hj_verdict hj_compare(hj_kind kind, double published, double computed, int *roundoff);

/* Signed difference shown in the report: ratio c/p for errors, counts,
 * ratios, exact counts and bounds (c itself for a zero bound); c - p for
 * orders and values. */
double hj_difference(hj_kind kind, double published, double computed);

/* The rules above as a Markdown list, for the report. */
void hj_compare_rules(FILE *out);

#ifdef __cplusplus
}
#endif

#endif
