/* fuzz_file.h -- the library's readers take a path: each input is written
 * to a temporary file of this process, removed after the run
 * (fuzz_file_done; libFuzzer ends without running atexit handlers). */
#ifndef FUZZ_FILE_H
#define FUZZ_FILE_H

#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char fuzz_path[256];

/* The path holding data[0..size), or NULL when it cannot be written. */
static const char *fuzz_file(const uint8_t *data, size_t size)
{
    if (!fuzz_path[0]) {
        /* /dev/shm: rewriting a file thousands of times a second on a
         * disk file system costs ten times more (truncation flushes). */
        const char *tmp = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : getenv("TMPDIR");
        snprintf(fuzz_path, sizeof fuzz_path, "%s/hj-fuzz.%ld", tmp && *tmp ? tmp : "/tmp", (long)getpid());
    }
    unlink(fuzz_path); /* a crashed run's, or a stranger's */
    int fd = open(fuzz_path, O_WRONLY | O_CREAT | O_EXCL, 0600);
    if (fd < 0) return NULL;
    size_t done = 0;
    while (done < size) {
        ssize_t n = write(fd, data + done, size - done);
        if (n <= 0) break;
        done += (size_t)n;
    }
    close(fd);
    return done == size ? fuzz_path : NULL;
}

static void fuzz_file_done(void) { unlink(fuzz_path); }

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
