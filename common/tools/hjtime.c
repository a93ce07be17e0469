/* hjtime -- run a command and record what it cost.
 *
 * Usage: hjtime OUT.tsv LABEL -- COMMAND [ARGS...]
 *
 * Runs COMMAND (its output and exit status pass through unchanged) and,
 * when it succeeds, writes OUT.tsv (atomically, see hj_io.h; its directory
 * is created if need be) with one row:
 *
 *     label  wall_s  cpu_s  peak_mb
 *
 * wall_s is the elapsed time, cpu_s the user + system time of the command
 * and everything it waited for, peak_mb its largest resident set (the
 * largest of its processes, from getrusage).  The report shows these as the run
 * times of the examples; they are never compared or tested.  A command that
 * fails leaves no OUT.tsv (an older one is removed), so a stale time is
 * never shown for a run that did not finish.  OUT.tsv must be absent or a
 * regular file (exit status 2 otherwise, before COMMAND runs).
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "hj_cli.h"
#include "hj_io.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char **argv)
{
    hj_cli_check_stdout("hjtime");
    if (argc == 2 && !strcmp(argv[1], "--help")) {
        printf("usage: hjtime OUT.tsv LABEL -- COMMAND [ARGS...]\n"
               "Runs COMMAND and, when it succeeds, writes OUT.tsv: label, wall_s, cpu_s, peak_mb.\n");
        return 0;
    }
    if (argc < 5 || strcmp(argv[3], "--")) {
        fprintf(stderr, "hjtime: usage: hjtime OUT.tsv LABEL -- COMMAND [ARGS...] (see --help)\n");
        return 2;
    }
    const char *out = argv[1], *label = argv[2];
    if (!*label || strpbrk(label, "\t\n")) {
        fprintf(stderr, "hjtime: the label must be non-empty, without tabs or newlines\n");
        return 2;
    }
    hj_error err;
    char *dir = strdup(out), *slash = dir ? strrchr(dir, '/') : NULL;
    if (slash) *slash = 0;
    int rc = slash && *dir ? hj_mkdirs(dir, &err) : 0;
    free(dir);
    if (rc) {
        fprintf(stderr, "hjtime: %s\n", err.msg);
        return 1;
    }
    /* Only a regular file is replaced (hj_io.h): a FIFO, link, device or
     * directory under the name is refused before the command runs. */
    if (hj_out_check(out, &err)) {
        fprintf(stderr, "hjtime: %s\n", err.msg);
        return 2;
    }
    remove(out);
    const double t0 = now();
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "hjtime: cannot start %s: %s\n", argv[4], strerror(errno));
        return 1;
    }
    if (pid == 0) {
        execvp(argv[4], argv + 4);
        fprintf(stderr, "hjtime: cannot run %s: %s\n", argv[4], strerror(errno));
        _exit(127);
    }
    int status;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) {
            fprintf(stderr, "hjtime: wait: %s\n", strerror(errno));
            return 1;
        }
    const double wall = now() - t0;
    struct rusage ru; /* of the one child waited for (POSIX: RUSAGE_CHILDREN) */
    getrusage(RUSAGE_CHILDREN, &ru);
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    if (WEXITSTATUS(status) != 0) return WEXITSTATUS(status);
    const double cpu = ru.ru_utime.tv_sec + 1e-6 * ru.ru_utime.tv_usec + ru.ru_stime.tv_sec + 1e-6 * ru.ru_stime.tv_usec;
    hj_out o;
    if (hj_out_open(&o, out, &err)) {
        fprintf(stderr, "hjtime: %s\n", err.msg);
        return 1;
    }
    fprintf(o.fp, "label\twall_s\tcpu_s\tpeak_mb\n%s\t%.2f\t%.2f\t%.1f\n", label, wall, cpu, ru.ru_maxrss / 1024.0);
    if (hj_out_commit(&o, &err)) {
        fprintf(stderr, "hjtime: %s\n", err.msg);
        return 1;
    }
    return 0;
}
