/* duel_evolve.c - the duel_evolve command: subcommand dispatch. */
#include <stdio.h>
#include <string.h>

#include "duel.h"
#include "duel_cli.h"

static void duel_usage(FILE *f)
{
    fprintf(f, "usage: duel_evolve run --config FILE --out DIR [--seed S] [--generations N] [--threads T] [--quiet] "
               "[--json] [--record-champion-games]\n"
               "       duel_evolve resume DIR [--generations N] [--set key=value ...] [--threads T] [--quiet] "
               "[--json] [--record-champion-games]\n"
               "       duel_evolve config --dump [--config FILE] [--set key=value ...]\n"
               "       duel_evolve ladder DIR\n"
               "       duel_evolve play A B [--games 288 | --food K --side west|east] [--trace FILE.csv] "
               "[--lcm-log FILE.lcm]\n"
               "       duel_evolve node controller BLOB --side west|east --lcm URL [--wait-ms N] [--timeout-ms N]\n"
               "       duel_evolve node world --food K|training --lcm URL [--timeout-ms N] [--wait-ms N] "
               "[--period-ms N] [--lcm-log FILE.lcm]\n"
               "       duel_evolve log info FILE.lcm\n"
               "       duel_evolve log dump FILE.lcm [--channel C]\n"
               "       duel_evolve inspect BLOB\n"
               "       duel_evolve dot BLOB [-o FILE.dot]\n"
               "       duel_evolve render (LOG.lcm | A B [--food K --side west|east]) --out DIR [--size 600] "
               "[--every N] [--sensors] [--video FILE.mp4] [--fps 30]\n"
               "       duel_evolve render-net BLOB --out FILE.png\n"
               "       duel_evolve export BLOB --c-array NAME [-o FILE.c]\n"
               "Robot duels of spec v%d (docs/duelsim.md).\n", DUEL_SPEC_VERSION);
}

int main(int argc, char **argv)
{
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        duel_usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    if (strcmp(argv[1], "run") == 0)
        return duel_cmd_run(argc - 2, argv + 2);
    if (strcmp(argv[1], "resume") == 0)
        return duel_cmd_resume(argc - 2, argv + 2);
    if (strcmp(argv[1], "config") == 0)
        return duel_cmd_config(argc - 2, argv + 2);
    if (strcmp(argv[1], "ladder") == 0)
        return duel_cmd_ladder(argc - 2, argv + 2);
    if (strcmp(argv[1], "play") == 0)
        return duel_cmd_play(argc - 2, argv + 2);
    if (strcmp(argv[1], "inspect") == 0)
        return duel_cmd_inspect(argc - 2, argv + 2);
    if (strcmp(argv[1], "dot") == 0)
        return duel_cmd_dot(argc - 2, argv + 2);
    if (strcmp(argv[1], "node") == 0)
        return duel_cmd_node(argc - 2, argv + 2);
    if (strcmp(argv[1], "log") == 0)
        return duel_cmd_log(argc - 2, argv + 2);
    if (strcmp(argv[1], "render") == 0)
        return duel_cmd_render(argc - 2, argv + 2);
    if (strcmp(argv[1], "render-net") == 0)
        return duel_cmd_render_net(argc - 2, argv + 2);
    if (strcmp(argv[1], "export") == 0)
        return duel_cmd_export(argc - 2, argv + 2);
    fprintf(stderr, "duel_evolve: unknown command '%s'\n", argv[1]);
    duel_usage(stderr);
    return 2;
}
