#include "hj_io.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char *dupstr(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d) memcpy(d, s, n);
    return d;
}

/* The temporary files open now, so that a signal can remove them: fixed
 * slots, since the handler may only call async-signal-safe functions. */
enum { OUT_SLOTS = 32, OUT_PATH = 1024 };
static char out_open_tmp[OUT_SLOTS][OUT_PATH];
static volatile sig_atomic_t out_slot_used[OUT_SLOTS];

static void out_register(const char *tmp)
{
    if (strlen(tmp) >= OUT_PATH) return;
    for (int k = 0; k < OUT_SLOTS; k++)
        if (!out_slot_used[k]) {
            memcpy(out_open_tmp[k], tmp, strlen(tmp) + 1);
            out_slot_used[k] = 1;
            return;
        }
}

static void out_unregister(const char *tmp)
{
    for (int k = 0; k < OUT_SLOTS; k++)
        if (out_slot_used[k] && !strcmp(out_open_tmp[k], tmp)) out_slot_used[k] = 0;
}

void hj_out_remove_all(void)
{
    for (int k = 0; k < OUT_SLOTS; k++)
        if (out_slot_used[k]) {
            unlink(out_open_tmp[k]);
            out_slot_used[k] = 0;
        }
}

static void out_on_signal(int sig)
{
    for (int k = 0; k < OUT_SLOTS; k++)
        if (out_slot_used[k]) unlink(out_open_tmp[k]);
    signal(sig, SIG_DFL);
    raise(sig);
}

void hj_out_remove_on_signal(void)
{
    const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    for (size_t k = 0; k < sizeof sigs / sizeof sigs[0]; k++) {
        struct sigaction sa;
        /* An ignored signal stays ignored (nohup, a background job of a
         * shell): the handler would make it kill the program. */
        if (sigaction(sigs[k], NULL, &sa) == 0 && sa.sa_handler == SIG_IGN) continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = out_on_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(sigs[k], &sa, NULL);
    }
}

/* The directory part of path ("." for a bare name, "/" for the root) in a
 * new string, or NULL; *base (may be NULL) points at path's last part. */
static char *dir_of(const char *path, const char **base)
{
    size_t n = strlen(path);
    char *dir = malloc(n + 2);
    if (!dir) return NULL;
    memcpy(dir, path, n + 1);
    char *slash = strrchr(dir, '/');
    if (base) *base = slash ? path + (slash - dir) + 1 : path;
    if (!slash) strcpy(dir, ".");
    else if (slash == dir) dir[1] = '\0';
    else *slash = '\0';
    return dir;
}

int hj_out_check(const char *path, hj_error *err)
{
    struct stat st;
    if (lstat(path, &st) == 0) {
        if (!S_ISREG(st.st_mode))
            return hj_error_set(err, HJ_EIO, "%s exists and is not a regular file: not replaced", path);
    } else if (errno != ENOENT) {
        return hj_error_set(err, HJ_EIO, "%s: %s", path, strerror(errno));
    }
    /* The directory must exist and take a new file. */
    char *dir = dir_of(path, NULL);
    if (!dir) return hj_error_set(err, HJ_ENOMEM, "out of memory");
    int ok = stat(dir, &st) == 0 && S_ISDIR(st.st_mode) && access(dir, W_OK | X_OK) == 0;
    int e = errno;
    int rc = ok ? HJ_OK
                : hj_error_set(err, HJ_EIO, "cannot write %s: %s: %s", path, dir,
                               stat(dir, &st) == 0 && !S_ISDIR(st.st_mode) ? "not a directory" : strerror(e));
    free(dir);
    return rc;
}

/* Remove "<path>.tmp.<pid>" files of processes that no longer exist: what
 * a killed run left behind. */
static void out_remove_stale(const char *path)
{
    const char *base;
    char *dir = dir_of(path, &base);
    if (!dir) return;
    size_t nb = strlen(base);
    DIR *d = opendir(dir);
    if (d) {
        struct dirent *e;
        while ((e = readdir(d)) != NULL) {
            const char *name = e->d_name;
            if (strncmp(name, base, nb) || strncmp(name + nb, ".tmp.", 5)) continue;
            char *end;
            long pid = strtol(name + nb + 5, &end, 10);
            if (*end || pid <= 0 || pid == (long)getpid()) continue;
            if (kill((pid_t)pid, 0) == 0 || errno != ESRCH) continue;
            char *full = malloc(strlen(dir) + strlen(name) + 2);
            if (!full) continue;
            sprintf(full, "%s/%s", dir, name);
            struct stat st;
            if (lstat(full, &st) == 0 && S_ISREG(st.st_mode)) unlink(full);
            free(full);
        }
        closedir(d);
    }
    free(dir);
}

int hj_out_open(hj_out *out, const char *path, hj_error *err)
{
    size_t n = strlen(path) + 32;
    out->fp = NULL;
    out->path = out->tmp = NULL;
    int rc = hj_out_check(path, err);
    if (rc) return rc;
    out_remove_stale(path);
    out->path = dupstr(path);
    out->tmp = malloc(n);
    if (!out->path || !out->tmp) {
        free(out->path);
        free(out->tmp);
        out->path = out->tmp = NULL;
        return hj_error_set(err, HJ_ENOMEM, "out of memory opening %s", path);
    }
    snprintf(out->tmp, n, "%s.tmp.%ld", path, (long)getpid());
    /* O_EXCL: never write through a link or into a file someone else made. */
    int fd = open(out->tmp, O_WRONLY | O_CREAT | O_EXCL, 0666);
    if (fd < 0 && errno == EEXIST) {
        struct stat st;
        if (lstat(out->tmp, &st) == 0 && S_ISREG(st.st_mode) && unlink(out->tmp) == 0)
            fd = open(out->tmp, O_WRONLY | O_CREAT | O_EXCL, 0666);
    }
    out->fp = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!out->fp) {
        int e = errno;
        if (fd >= 0) close(fd), unlink(out->tmp);
        free(out->path);
        free(out->tmp);
        out->path = out->tmp = NULL;
        return hj_error_set(err, HJ_EIO, "cannot write %s: %s", path, strerror(e));
    }
    out_register(out->tmp);
    return HJ_OK;
}

static void out_release(hj_out *out)
{
    if (out->tmp) out_unregister(out->tmp);
    free(out->path);
    free(out->tmp);
    out->path = out->tmp = NULL;
    out->fp = NULL;
}

void hj_out_abort(hj_out *out)
{
    if (out->fp) fclose(out->fp);
    if (out->tmp) remove(out->tmp);
    out_release(out);
}

int hj_out_commit(hj_out *out, hj_error *err)
{
    int bad = ferror(out->fp) != 0;
    bad |= fflush(out->fp) != 0;
    int e = errno;
    bad |= fclose(out->fp) != 0;
    out->fp = NULL;
    if (bad) {
        remove(out->tmp);
        int rc = hj_error_set(err, HJ_EIO, "error writing %s: %s", out->path, strerror(e));
        out_release(out);
        return rc;
    }
    /* The target may have changed since it was opened. */
    if (hj_out_check(out->path, err)) {
        remove(out->tmp);
        int rc = err ? err->code : HJ_EIO;
        out_release(out);
        return rc;
    }
    if (rename(out->tmp, out->path) != 0) {
        e = errno;
        remove(out->tmp);
        int rc = hj_error_set(err, HJ_EIO, "cannot rename onto %s: %s", out->path, strerror(e));
        out_release(out);
        return rc;
    }
    out_release(out);
    return HJ_OK;
}

/* ---- TSV tables ------------------------------------------------------ */

/* One line without its end; *bad = 1 when it is too long, 2 when it holds
 * a NUL byte (then NULL). */
static char *read_line(FILE *fp, int *bad)
{
    size_t cap = 256, len = 0;
    char *buf = malloc(cap);
    int c;
    *bad = 0;
    if (!buf) return NULL;
    while ((c = fgetc(fp)) != EOF && c != '\n') {
        if (c == '\0') { *bad = 2; free(buf); return NULL; }
        if (len + 1 >= cap) {
            if (cap > (1u << 20)) { *bad = 1; free(buf); return NULL; }
            char *nb = realloc(buf, cap * 2);
            if (!nb) { free(buf); return NULL; }
            buf = nb;
            cap *= 2;
        }
        buf[len++] = (char)c;
    }
    if (c == EOF && len == 0) { free(buf); return NULL; }
    if (len > 0 && buf[len - 1] == '\r') len--;
    buf[len] = '\0';
    return buf;
}

/* Split s at tabs in place; returns count, fills at most max pointers. */
static int split_tabs(char *s, char **parts, int max)
{
    int n = 0;
    char *p = s;
    for (;;) {
        char *t = strchr(p, '\t');
        if (n < max) parts[n] = p;
        n++;
        if (!t) break;
        *t = '\0';
        p = t + 1;
    }
    return n;
}

static int push_meta(hj_table *t, const char *line)
{
    /* "# key: value" with key a single word */
    const char *p = line + 1;
    while (*p == ' ') p++;
    const char *k = p;
    while (*p && *p != ':' && *p != ' ' && *p != '\t') p++;
    if (*p != ':' || p == k) return HJ_OK;
    size_t klen = (size_t)(p - k);
    p++;
    while (*p == ' ' || *p == '\t') p++;
    char **nk = realloc(t->meta_key, sizeof(char *) * (size_t)(t->nmeta + 1));
    if (!nk) return HJ_ENOMEM;
    t->meta_key = nk;
    char **nv = realloc(t->meta_val, sizeof(char *) * (size_t)(t->nmeta + 1));
    if (!nv) return HJ_ENOMEM;
    t->meta_val = nv;
    char *key = malloc(klen + 1);
    char *val = dupstr(p);
    if (!key || !val) { free(key); free(val); return HJ_ENOMEM; }
    memcpy(key, k, klen);
    key[klen] = '\0';
    t->meta_key[t->nmeta] = key;
    t->meta_val[t->nmeta] = val;
    t->nmeta++;
    return HJ_OK;
}

FILE *hj_in_open(const char *path, const char *mode, hj_error *err)
{
    FILE *f = fopen(path, mode);
    struct stat st;
    if (f && fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
        fclose(f);
        f = NULL;
        errno = EISDIR;
    }
    if (!f) hj_error_set(err, HJ_EIO, "cannot read %s: %s", path, strerror(errno));
    return f;
}

int hj_table_read(hj_table *t, const char *path, hj_error *err)
{
    memset(t, 0, sizeof *t);
    FILE *fp = hj_in_open(path, "r", err);
    if (!fp) return HJ_EIO;
    int lineno = 0, rc = HJ_OK, bad = 0;
    char *line;
    size_t rowcap = 0;
    while ((line = read_line(fp, &bad)) != NULL) {
        lineno++;
        if (line[0] == '#') {
            if (push_meta(t, line) != HJ_OK) { free(line); rc = hj_error_set(err, HJ_ENOMEM, "out of memory reading %s", path); break; }
            free(line);
            continue;
        }
        if (line[0] == '\0') { free(line); continue; }
        int n = 1;
        for (const char *q = line; *q; q++) n += *q == '\t';
        char **parts = malloc(sizeof(char *) * (size_t)n);
        if (!parts) { free(line); rc = hj_error_set(err, HJ_ENOMEM, "out of memory reading %s", path); break; }
        split_tabs(line, parts, n);
        char **copy = malloc(sizeof(char *) * (size_t)n);
        int ok = copy != NULL;
        for (int i = 0; ok && i < n; i++) {
            copy[i] = dupstr(parts[i]);
            if (!copy[i]) { for (int j = 0; j < i; j++) free(copy[j]); ok = 0; }
        }
        free(parts);
        free(line);
        if (!ok) { free(copy); rc = hj_error_set(err, HJ_ENOMEM, "out of memory reading %s", path); break; }
        if (!t->cols) {
            t->cols = copy;
            t->ncols = n;
            continue;
        }
        if (n != t->ncols) {
            for (int i = 0; i < n; i++) free(copy[i]);
            free(copy);
            rc = hj_error_set(err, HJ_EFORMAT, "%s:%d: %d cell%s, expected %d (tab-separated)", path, lineno, n,
                               hj_plural(n), t->ncols);
            break;
        }
        if ((size_t)t->nrows == rowcap) {
            size_t nc = rowcap ? 2 * rowcap : 16;
            char ***nr = realloc(t->cells, nc * sizeof(char **));
            if (!nr) {
                for (int i = 0; i < n; i++) free(copy[i]);
                free(copy);
                rc = hj_error_set(err, HJ_ENOMEM, "out of memory reading %s", path);
                break;
            }
            t->cells = nr;
            rowcap = nc;
        }
        t->cells[t->nrows++] = copy;
    }
    if (rc == HJ_OK && bad)
        rc = hj_error_set(err, HJ_EFORMAT, "%s:%d: %s", path, lineno + 1, bad == 1 ? "line too long" : "a NUL byte");
    if (rc == HJ_OK && ferror(fp)) rc = hj_error_set(err, HJ_EIO, "error reading %s", path);
    if (rc == HJ_OK && !t->cols) rc = hj_error_set(err, HJ_EFORMAT, "%s: no header line with column names", path);
    fclose(fp);
    if (rc != HJ_OK) hj_table_free(t);
    return rc;
}

void hj_table_free(hj_table *t)
{
    for (int r = 0; r < t->nrows; r++) {
        for (int c = 0; c < t->ncols; c++) free(t->cells[r][c]);
        free(t->cells[r]);
    }
    free(t->cells);
    if (t->cols)
        for (int c = 0; c < t->ncols; c++) free(t->cols[c]);
    free(t->cols);
    for (int i = 0; i < t->nmeta; i++) {
        free(t->meta_key[i]);
        free(t->meta_val[i]);
    }
    free(t->meta_key);
    free(t->meta_val);
    memset(t, 0, sizeof *t);
}

int hj_table_col(const hj_table *t, const char *name)
{
    for (int c = 0; c < t->ncols; c++)
        if (strcmp(t->cols[c], name) == 0) return c;
    return -1;
}

const char *hj_table_meta(const hj_table *t, const char *key)
{
    for (int i = 0; i < t->nmeta; i++)
        if (strcmp(t->meta_key[i], key) == 0) return t->meta_val[i];
    return NULL;
}

int hj_mkdirs(const char *path, hj_error *err)
{
    if (path[0] == '\0') return hj_error_set(err, HJ_EINVAL, "an empty directory name");
    char *p = dupstr(path);
    if (!p) return hj_error_set(err, HJ_ENOMEM, "out of memory");
    for (char *s = p + 1; ; s++) {
        if (*s == '/' || *s == '\0') {
            char c = *s;
            *s = '\0';
            struct stat st;
            if (mkdir(p, 0777) != 0 && (errno != EEXIST || stat(p, &st) != 0 || !S_ISDIR(st.st_mode))) {
                if (errno == EEXIST) errno = ENOTDIR;
                int e = errno;
                int rc = hj_error_set(err, HJ_EIO, "cannot create directory %s: %s", p, strerror(e));
                free(p);
                return rc;
            }
            *s = c;
            if (c == '\0') break;
        }
    }
    free(p);
    return HJ_OK;
}
