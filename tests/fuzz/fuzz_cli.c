/* libFuzzer target: the command-line readers: hj_cli_parse against a
 * table of every option type (the input is argv, NUL-separated), then
 * --help and --list-options from what was parsed, and the word parsers
 * of the toolbox (hj_ls_accuracy_parse). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hj_cli.h"
#include "hj_ls_accuracy.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    enum { MAXARG = 32 };
    char *buf = malloc(size + 1);
    if (!buf) return 0;
    memcpy(buf, data, size);
    buf[size] = '\0';
    char *argv[MAXARG + 1] = {"prog"};
    int argc = 1;
    for (size_t k = 0; k <= size && argc < MAXARG;) {
        argv[argc++] = buf + k;
        k += strlen(buf + k) + 1;
    }
    long N = 10, sizes[4] = {8, 16};
    double cfl = 0.5;
    const char *out = "x";
    int nsizes = 2, quick = 0, scheme = 0, acc;
    static const char *const schemes[] = {"eno2", "weno5", NULL};
    hj_cli_opt opts[] = {
        {.name = "--N", .type = HJ_OPT_LONG, .value = &N, .min = 2, .max = 1000, .metavar = "N", .help = "n"},
        {.name = "--cfl", .type = HJ_OPT_DOUBLE, .value = &cfl, .min = 1e-300, .max = 1, .metavar = "C"},
        {.name = "--out", .type = HJ_OPT_STRING, .value = &out, .metavar = "FILE"},
        {.name = "--sizes", .type = HJ_OPT_LONG_LIST, .value = sizes, .min = 8, .max = 100, .count = &nsizes, .maxn = 4},
        {.name = "--quick", .type = HJ_OPT_FLAG, .value = &quick},
        {.name = "--scheme", .type = HJ_OPT_CHOICE, .value = &scheme, .choices = schemes},
    };
    hj_cli_spec spec = {"prog", "fuzzed", opts, (int)(sizeof opts / sizeof opts[0]), NULL};
    int help = 0;
    hj_error err;
    if (hj_cli_parse(&spec, argc, argv, &help, &err) == HJ_OK) {
        FILE *devnull = fopen("/dev/null", "w");
        if (devnull) {
            hj_cli_help(&spec, devnull);
            hj_cli_list(&spec, devnull);
            fclose(devnull);
        }
    } else if (!err.msg[0]) {
        abort();
    }
    for (int k = 1; k < argc; k++) (void)hj_ls_accuracy_parse(argv[k], &acc, &err);
    free(buf);
    return 0;
}
