/*
 * Writes the decompressed event stream of an apitrace trace (the Snappy
 * container: "at", then blocks of a 4-byte little-endian length and that
 * many compressed bytes) to standard output: the fuzzer's seed format.
 */
#include <snappy-c.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: unpack_trace TRACE > RAW\n");
        return 2;
    }
    FILE *f = fopen(argv[1], "rb");
    unsigned char m[2];
    if (!f || fread(m, 1, 2, f) != 2 || m[0] != 'a' || m[1] != 't') {
        fprintf(stderr, "unpack_trace: %s: not a Snappy apitrace trace\n", argv[1]);
        return 1;
    }
    unsigned char l[4];
    while (fread(l, 1, 4, f) == 4) {
        size_t clen = (size_t)l[0] | (size_t)l[1] << 8 | (size_t)l[2] << 16 | (size_t)l[3] << 24, n;
        char *in = malloc(clen ? clen : 1), *out = NULL;
        if (!in || fread(in, 1, clen, f) != clen || snappy_uncompressed_length(in, clen, &n) != SNAPPY_OK ||
            !(out = malloc(n ? n : 1)) || snappy_uncompress(in, clen, out, &n) != SNAPPY_OK) {
            fprintf(stderr, "unpack_trace: %s: bad block\n", argv[1]);
            return 1;
        }
        fwrite(out, 1, n, stdout);
        free(in);
        free(out);
    }
    fclose(f);
    return 0;
}
