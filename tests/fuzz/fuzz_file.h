/* fuzz_file.h -- the library's readers take a path: each input is written
 * to one temporary file per fuzzing process, rewritten for every run. */
#ifndef FUZZ_FILE_H
#define FUZZ_FILE_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char fuzz_path[256];
static int fuzz_fd = -1;

static void fuzz_file_remove(void)
{
    if (fuzz_fd >= 0) unlink(fuzz_path);
}

/* The path holding data[0..size), or NULL when it cannot be written. */
static const char *fuzz_file(const uint8_t *data, size_t size)
{
    if (fuzz_fd < 0) {
        /* /dev/shm: rewriting a file thousands of times a second on a
         * disk file system costs ten times more (truncation flushes). */
        const char *tmp = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : getenv("TMPDIR");
        snprintf(fuzz_path, sizeof fuzz_path, "%s/hj-fuzz.XXXXXX", tmp && *tmp ? tmp : "/tmp");
        fuzz_fd = mkstemp(fuzz_path);
        if (fuzz_fd < 0) return NULL;
        atexit(fuzz_file_remove);
    }
    if (ftruncate(fuzz_fd, 0) != 0) return NULL;
    size_t done = 0;
    while (done < size) {
        ssize_t n = pwrite(fuzz_fd, data + done, size - done, (off_t)done);
        if (n <= 0) return NULL;
        done += (size_t)n;
    }
    return fuzz_path;
}

/* A reader's message is one non-empty line with no control byte (what it
 * quotes from the file is escaped). */
static int fuzz_message_ok(const char *msg)
{
    if (!msg[0]) return 0;
    for (const unsigned char *p = (const unsigned char *)msg; *p; p++)
        if (*p < 0x20 || *p == 0x7f) return 0;
    return 1;
}

#endif
