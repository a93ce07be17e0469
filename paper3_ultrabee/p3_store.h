/* p3_store.h -- storage of the nodes around a front (section 3 of
 * Bokanowski, Cristiani & Zidani 2010), all behind one interface.
 *
 * A store holds a set D of nodes of the grid {0..N-1}^d (d = 2, 3, 4) and
 * one double value per node.  Kinds:
 *
 *   P3_FS   full storage: every node is stored (D is the whole grid).
 *   P3_FLS  full & list storage (classical narrow band): a full array of
 *           values, a state byte per node and an unsorted list of the band
 *           nodes; new nodes are appended, removed ones are dropped lazily.
 *   P3_LS   list storage: one doubly linked list of (compressed index,
 *           value), ordered by the compressed index; search walks forward or
 *           backward from the last node found.
 *   P3_CRS  compressed row storage with dynamic rows: N lists, one per
 *           first index, ordered by the compressed remaining indices and
 *           searched from the row's head.
 *   P3_SSD  sparse semi-dynamic: a static (d-1)-dimensional array of list
 *           heads, each list ordered by the last index and holding
 *           (last index, value) of the stored nodes of that line, searched
 *           from the line's head.
 *   P3_SSDC Remark 3.1 variant of SSD: no NULL heads; only the non-empty
 *           lines are kept, in a list ordered by line number (a sorted
 *           array here, searched by bisection).
 *
 * List cells of LS, CRS and SSD are allocated from one pool per list (and
 * linked by 32-bit indices), so that walking a list stays in cache; the
 * list structure itself is the textbook one.
 *
 * Library code: nothing is printed; failures return HJ_* codes.  Out of
 * memory is HJ_ENOMEM, including for the full kinds above a few GB.
 */
#ifndef P3_STORE_H
#define P3_STORE_H

#include <stddef.h>
#include <stdint.h>

#include "hj_error.h"

#define P3_DMAX 4

typedef enum { P3_FS, P3_FLS, P3_LS, P3_CRS, P3_SSD, P3_SSDC, P3_SSDA, P3_NKINDS } p3_kind;

typedef struct p3_store p3_store;

/* Name ("FS", "FLS", "LS", "CRS", "SSD", "SSDC", "SSDA") and its inverse (-1 if unknown). */
const char *p3_kind_name(p3_kind k);
int p3_kind_from_name(const char *name);

/* A new empty store for the grid {0..n-1}^d (FS: every node, value 1).
 * HJ_EINVAL for d outside 2..4 or n < 1, HJ_ENOMEM when it does not fit. */
int p3_store_new(p3_store **out, p3_kind kind, int d, int n, hj_error *err);
void p3_store_free(p3_store *s);

p3_kind p3_store_kind(const p3_store *s);

/* Pointer to the value of node idx (d indices in 0..n-1), or NULL when the
 * node is not stored.  Valid until the next insert or remove. */
double *p3_store_find(p3_store *s, const int *idx);

/* The m <= 3 nodes idx + k e_{d-1}, k = 0..m-1, consecutive along the
 * last index (idx[0..d-2] in 0..n-1; idx[d-1] may be -1): out[k] as
 * p3_store_find would give it, NULL when not stored or outside the grid.
 * The list kinds (LS, CRS, SSD, SSDC) hold the m nodes next to each other
 * in one sorted list, and each list remembers the cell last found, inserted
 * or next to a removed one: the search starts there and walks forward or
 * backward (as LS always does), then steps along the run.  This is the
 * scheme's lookup (p3_ub.c), which visits the band in the store's order so
 * that each neighbouring line is asked for nearby keys again and again;
 * p3_store_find keeps each structure's own search (Tables 1-2 time it).
 * Pointers valid until the next insert or remove. */
void p3_store_find_run(p3_store *s, const int *idx, int m, double **out);

/* Store node idx with value v (overwrites the value if already stored). */
int p3_store_insert(p3_store *s, const int *idx, double v, hj_error *err);

/* Remove node idx if stored (FS: nothing happens). */
void p3_store_remove(p3_store *s, const int *idx);

/* Number of stored nodes, and bytes currently allocated by the store. */
size_t p3_store_count(const p3_store *s);
size_t p3_store_bytes(const p3_store *s);

/* Visit every stored node once, in the store's order (lexicographic for
 * FS, LS, CRS, SSD, SSDC and SSDA; insertion order for FLS).  fn must not
 * insert or remove.  A non-zero return of fn stops the walk and is
 * returned. */
typedef int (*p3_visit_fn)(const int *idx, double *v, void *ctx);
int p3_store_foreach(p3_store *s, p3_visit_fn fn, void *ctx);

#endif
