/* host_main.c - the firmware example's games on the workstation: the same fw_duels.c, champions read from blob files, lines to stdout. */
#include <stdio.h>
#include <stdlib.h>

#include "fw_duels.h"
#include "fw_port.h"

#define FW_HOST_EXIT_USAGE 4 /* not a target status: bad arguments or an unreadable file */
#define FW_HOST_BLOB_MAX (NRT_HEADER_SIZE + NRT_CONN_SIZE * 65535u)

static void fw_host_write(void *ud, const char *s, size_t n)
{
    fwrite(s, 1, n, (FILE *)ud);
}

/* The whole file into a malloc'd buffer; NULL after a message on stderr. */
static uint8_t *fw_host_read(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    uint8_t *b = (uint8_t *)malloc(FW_HOST_BLOB_MAX + 1);
    size_t n = 0;

    if (f == NULL || b == NULL) {
        fprintf(stderr, "fw_duels_host: %s: cannot read\n", path);
        if (f != NULL)
            fclose(f);
        free(b);
        return NULL;
    }
    n = fread(b, 1, FW_HOST_BLOB_MAX + 1, f);
    if (ferror(f) || n > FW_HOST_BLOB_MAX) {
        fprintf(stderr, "fw_duels_host: %s: cannot read, or larger than any blob\n", path);
        fclose(f);
        free(b);
        return NULL;
    }
    fclose(f);
    *len = n;
    return b;
}

int main(int argc, char **argv)
{
    static uint8_t arena[FW_ARENA]; /* the target's size, so memory refusals match too */
    uint8_t *blob[2] = {NULL, NULL}, *world = NULL;
    size_t len[2] = {0, 0}, world_len = 0;
    int rc = FW_HOST_EXIT_USAGE;

    if (argc != 3 && argc != 4) {
        fprintf(stderr, "usage: fw_duels_host A.blob B.blob [WORLD.bin]\n"
                        "Plays the firmware example's games (examples/firmware) on this machine, in world v1 or in\n"
                        "the world whose rules WORLD.bin holds (duel_evolve export --world SPEC --raw -o WORLD.bin).\n");
        return FW_HOST_EXIT_USAGE;
    }
    if (argc == 4 && (world = fw_host_read(argv[3], &world_len)) == NULL)
        return FW_HOST_EXIT_USAGE;
    blob[0] = fw_host_read(argv[1], &len[0]);
    blob[1] = blob[0] != NULL ? fw_host_read(argv[2], &len[1]) : NULL;
    if (blob[1] != NULL) {
        const uint8_t *const cb[2] = {blob[0], blob[1]};
        rc = fw_duels_run(cb, len, world, world_len, arena, sizeof arena, fw_host_write, stdout);
        if (fflush(stdout) != 0 || ferror(stdout)) {
            fprintf(stderr, "fw_duels_host: cannot write the output\n");
            rc = FW_HOST_EXIT_USAGE;
        }
    }
    free(blob[0]);
    free(blob[1]);
    free(world);
    return rc;
}
