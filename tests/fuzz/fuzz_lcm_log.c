/* fuzz_lcm_log.c - libFuzzer harness: any bytes as an LCM event log through the game reader, the replay frames and `duel_evolve log info` / `log dump` (every channel). */
#define _POSIX_C_SOURCE 200809L
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "duel_cli.h"
#include "duel_lcm.h"
#include "duel_replay.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char fl_path[64];

static void fl_cleanup(void)
{
    unlink(fl_path);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    /* the commands print: run with -close_fd_mask=3 (scripts/fuzz.sh), libFuzzer keeps its own output */
    snprintf(fl_path, sizeof fl_path, "/tmp/fuzz_lcm_log.%ld.lcm", (long)getpid());
    atexit(fl_cleanup);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const channels[] = {DUEL_CH_STATE, DUEL_CH_SENSE_WEST, DUEL_CH_SENSE_EAST, DUEL_CH_MOTOR_WEST,
                                           DUEL_CH_MOTOR_EAST};
    char err[4400], *argv[4];
    duel_lcm_game *g;
    duel_replay r;
    FILE *f = fopen(fl_path, "wb");
    int k;
    if (f == NULL || fwrite(data, 1, size, f) != size || fclose(f) != 0)
        abort();
    err[0] = '\0';
    if (duel_lcm_game_read(&g, fl_path, err, sizeof err) != 0 && err[0] == '\0')
        __builtin_trap(); /* a refusal always says why */
    duel_lcm_game_free(g);
    duel_replay_init(&r);
    (void)duel_replay_from_lcm_log(&r, fl_path, err, sizeof err);
    duel_replay_free(&r);
    argv[0] = (char *)"info";
    argv[1] = fl_path;
    (void)duel_cmd_log(2, argv);
    argv[0] = (char *)"dump";
    (void)duel_cmd_log(2, argv);
    argv[2] = (char *)"--channel";
    for (k = 0; k < 5; k++) {
        argv[3] = (char *)channels[k];
        (void)duel_cmd_log(4, argv);
    }
    clearerr(stdout);
    return 0;
}
