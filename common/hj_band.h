/* hj_band.h -- the nodes of a narrow band around a front and their values,
 * kept in one of the storage structures of section 3 of Bokanowski,
 * Cristiani & Zidani 2010 (FS, FLS, LS, CRS, the sparse semi-dynamic SSD
 * and its Remark 3.1 variant SSDC), or in SSDA (SSD with contiguous lines,
 * not in the paper), all behind one interface.
 *
 * A store holds a set D of nodes of the grid {0..N-1}^d (d = 2, 3, 4) and
 * one double value per node.  Kinds:
 *
 *   HJ_BAND_FS   full storage: every node is stored (D is the whole grid).
 *   HJ_BAND_FLS  full & list storage (classical narrow band): a full array of
 *           values, a state byte per node and an unsorted list of the band
 *           nodes; new nodes are appended, removed ones are dropped lazily.
 *   HJ_BAND_LS   list storage: one doubly linked list of (compressed index,
 *           value), ordered by the compressed index; search walks forward or
 *           backward from the last node found.
 *   HJ_BAND_CRS  compressed row storage with dynamic rows: N lists, one per
 *           first index, ordered by the compressed remaining indices and
 *           searched from the row's head.
 *   HJ_BAND_SSD  sparse semi-dynamic: a static (d-1)-dimensional array of list
 *           heads, each list ordered by the last index and holding
 *           (last index, value) of the stored nodes of that line, searched
 *           from the line's head.
 *   HJ_BAND_SSDC Remark 3.1 variant of SSD: no NULL heads; only the non-empty
 *           lines are kept, in a list ordered by line number (a sorted
 *           array here, searched by bisection).
 *   HJ_BAND_SSDA SSD with a contiguous sorted array per line instead of a
 *           linked list (searched by bisection).
 *
 * List cells of LS, CRS and SSD are allocated from one pool per list (and
 * linked by 32-bit indices, the keys and links apart from the values), so
 * that walking a list stays in cache; the list structure itself is the
 * textbook one.
 *
 * Library code: nothing is printed; failures return HJ_* codes.  Out of
 * memory is HJ_ENOMEM, including for the full kinds above a few GB.
 */
#ifndef HJ_BAND_H
#define HJ_BAND_H

#include <stddef.h>
#include <stdint.h>

#include "hj_error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define HJ_BAND_DMAX 4

typedef enum {
    HJ_BAND_FS, HJ_BAND_FLS, HJ_BAND_LS, HJ_BAND_CRS, HJ_BAND_SSD, HJ_BAND_SSDC, HJ_BAND_SSDA, HJ_BAND_NKINDS
} hj_band_kind;

typedef struct hj_band hj_band;

/* Name ("FS", "FLS", "LS", "CRS", "SSD", "SSDC", "SSDA") and its inverse (-1 if unknown). */
const char *hj_band_kind_name(hj_band_kind k);
int hj_band_kind_from_name(const char *name);

/* A new empty store for the grid {0..n-1}^d (FS: every node, value 1).
 * HJ_EINVAL for d outside 2..4 or n < 1, HJ_ENOMEM when it does not fit. */
int hj_band_new(hj_band **out, hj_band_kind kind, int d, int n, hj_error *err);
void hj_band_free(hj_band *s);

hj_band_kind hj_band_kind_of(const hj_band *s);
/* The grid of the store: dimension d and nodes per direction n. */
int hj_band_dim(const hj_band *s);
int hj_band_size(const hj_band *s);

/* Pointer to the value of node idx (d indices in 0..n-1), or NULL when the
 * node is not stored.  Valid until the next insert or remove. */
double *hj_band_find(hj_band *s, const int *idx);

/* The m nodes idx + k e_{d-1}, k = 0..m-1, consecutive along the last
 * index (idx[0..d-2] in 0..n-1; idx[d-1] may be -1): out[k] as
 * hj_band_find would give it, NULL when not stored or outside the grid.
 * The list kinds (LS, CRS, SSD, SSDC) hold the m nodes next to each other
 * in one sorted list, and each list remembers the cell last found, inserted
 * or next to a removed one: the search starts there and walks forward or
 * backward (as LS always does), then steps along the run.  This is the
 * scheme's lookup (hj_ub.c: one run per segment of the band and
 * neighbouring line), which visits the band in the store's order so
 * that each neighbouring line is asked for nearby keys again and again;
 * hj_band_find keeps each structure's own search (Tables 1-2 time it).
 * Pointers valid until the next insert or remove. */
void hj_band_find_run(hj_band *s, const int *idx, int m, double **out);

/* Store node idx with value v (overwrites the value if already stored). */
int hj_band_insert(hj_band *s, const int *idx, double v, hj_error *err);

/* Store node idx with value v, for building a store from nodes given in
 * lexicographic order: the list kinds (LS, CRS, SSD, SSDC) link it after
 * the last cell of its list, found from the list's last position (O(1) per
 * node when every node is appended), instead of searching for its place
 * from the head; the other kinds insert as hj_band_insert.  HJ_EINVAL
 * (store unchanged) when idx is not above every node of its list (SSDA:
 * of its line); FS and FLS accept any node. */
int hj_band_append(hj_band *s, const int *idx, double v, hj_error *err);

/* Remove node idx if stored (FS: nothing happens). */
void hj_band_remove(hj_band *s, const int *idx);

/* hj_band_insert and hj_band_remove with the search of hj_band_find_run:
 * the list kinds (CRS, SSD, SSDC as LS) walk from the cell last found,
 * inserted or next to a removed one, instead of from the list's head.
 * The store afterwards is the same, cell for cell and link for link (a
 * sorted list has one place for a key; the search's start changes only
 * the walk).  For the scheme's inserts and removals next to the nodes it
 * has just looked up (hj_ub.c): from the head, a line of m band nodes
 * cost O(m) per insert, O(m^2) per step for a face along a line. */
int hj_band_insert_near(hj_band *s, const int *idx, double v, hj_error *err);
void hj_band_remove_near(hj_band *s, const int *idx);

/* Number of stored nodes, and bytes currently allocated by the store. */
size_t hj_band_count(const hj_band *s);
size_t hj_band_bytes(const hj_band *s);

/* Visit every stored node once, in the store's order (lexicographic for
 * FS, LS, CRS, SSD, SSDC and SSDA; insertion order for FLS).  fn must not
 * insert or remove.  A non-zero return of fn stops the walk and is
 * returned. */
typedef int (*hj_band_visit_fn)(const int *idx, double *v, void *ctx);
int hj_band_foreach(hj_band *s, hj_band_visit_fn fn, void *ctx);

#ifdef __cplusplus
}
#endif

#endif
