/* hj_io.h -- files that are never seen half-written, and the plain TSV
 * tables that carry published and computed values through the pipeline.
 *
 * Atomic output: hj_out_open() opens "<path>.tmp.<pid>"; hj_out_commit()
 * flushes, closes and renames it over <path>.  An interrupted run leaves at
 * most a *.tmp.* file, never a truncated table under the final name, and
 * the next run writing the same path removes it.  Only regular files are
 * ever replaced.
 *
 * TSV tables: lines starting with '#' are comments; a comment of the form
 * "# name: value" is a header field (hj_table_meta).  The first other line
 * holds the column names, every further non-empty line one row with exactly
 * as many tab-separated cells.
 */
#ifndef HJ_IO_H
#define HJ_IO_H

#include <stdio.h>

#include "hj_error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    FILE *fp;
    char *path;
    char *tmp;
} hj_out;

/* Whether path may be written: it is absent or a regular file (a device,
 * FIFO, directory or symbolic link is never replaced), and its directory
 * exists and is writable.  Programs call it before a long computation, so
 * that a bad output location fails first. */
int hj_out_check(const char *path, hj_error *err);

/* Open a temporary file next to path for writing (after hj_out_check; a
 * leftover "<path>.tmp.<pid>" of a process that no longer exists is
 * removed first); out->fp is the stream. */
int hj_out_open(hj_out *out, const char *path, hj_error *err);
/* Flush, close and rename over the final path.  On failure the temporary
 * file is removed.  The hj_out is released in every case. */
int hj_out_commit(hj_out *out, hj_error *err);
/* Close and remove the temporary file (after an error). */
void hj_out_abort(hj_out *out);

/* fopen(path, mode) for reading, refusing a directory (which fopen opens
 * and whose reads then fail with a bare "error reading"): NULL with
 * "cannot read PATH: reason" (HJ_EIO) in err. */
FILE *hj_in_open(const char *path, const char *mode, hj_error *err);

/* For programs: on SIGINT, SIGTERM or SIGHUP remove every temporary file
 * still open, then die of the signal as before; a signal the process
 * ignores (nohup) stays ignored.  The library never installs it by itself
 * (hj_cli_parse_or_exit does, for the programs). */
void hj_out_remove_on_signal(void);

/* For programs that exit on an error: remove every temporary file still
 * open (hj_cli_fail calls it), so that a failed run leaves none. */
void hj_out_remove_all(void);

typedef struct {
    int ncols, nrows;
    char **cols;   /* ncols column names */
    char ***cells; /* nrows rows of ncols cells */
    int nmeta;
    char **meta_key, **meta_val;
} hj_table;

int hj_table_read(hj_table *t, const char *path, hj_error *err);
void hj_table_free(hj_table *t);
/* Index of a column, or -1. */
int hj_table_col(const hj_table *t, const char *name);
/* Value of the header field "# key: value", or NULL. */
const char *hj_table_meta(const hj_table *t, const char *key);

/* Create a directory and its parents (like mkdir -p). */
int hj_mkdirs(const char *path, hj_error *err);

#ifdef __cplusplus
}
#endif

#endif
