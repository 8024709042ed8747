/* duel_evolve.c - the duel_evolve command: subcommand dispatch. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "duel.h"
#include "neat.h"
#include "duel_cli.h"
#include "duel_html.h"
#include "duel_text.h"
#include "duel_mpi.h"

static void duel_usage(FILE *f)
{
    fprintf(f, "usage: duel_evolve --version | --help | COMMAND --help\n"
               "       duel_evolve run --config FILE --out DIR [--set key=value ...] [--seed S] [--generations N] [--threads T] [--quiet] "
               "[--json] [--record-champion-games]\n"
               "       duel_evolve resume DIR [--generations N [--shorten]] [--set key=value ...] [--threads T] [--quiet] "
               "[--json] [--record-champion-games]\n"
               "       duel_evolve config --dump [--config FILE] [--set key=value ...]\n"
               "       duel_evolve ladder DIR [--top | --levels L1-L2] [--against NAME,...] [--csv FILE] [--force] [--json]\n"
               "       duel_evolve compare RUN... --against RUN... [--threads T] [--json FILE] [--csv FILE] "
               "[--cache FILE] [--force]\n"
               "       duel_evolve experiment PLAN --out DIR [--set key=value ...] [--jobs J] [--threads T] [--quiet]\n"
               "       duel_evolve experiment resume DIR [--jobs J] [--threads T] [--quiet]\n"
               "       duel_evolve experiment report DIR [--html [--games top|all|none] [--embed]]\n"
               "       duel_evolve report RUN --html DIR [--games all|top|none] [--embed] [--force]\n"
               "       duel_evolve play A B [--games 288 | --food K --side west|east] [--trace FILE.csv] "
               "[--lcm-log FILE.lcm] [--force] [--json]\n"
               "       duel_evolve node controller BLOB --side west|east --lcm URL [--wait-ms N] [--timeout-ms N]\n"
               "       duel_evolve node world --food K|training --lcm URL [--timeout-ms N] [--wait-ms N] "
               "[--period-ms N] [--lcm-log FILE.lcm [--force]]\n"
               "       duel_evolve log info FILE.lcm\n"
               "       duel_evolve log dump FILE.lcm [--channel C]\n"
               "       duel_evolve inspect BLOB | GENOME | RUN_DIR | CHECKPOINT\n"
               "       duel_evolve dot BLOB|GENOME [-o FILE.dot [--force]] [--min-weight W]\n"
               "       duel_evolve render (LOG.lcm | A B [--food K --side west|east]) --out DIR [--size 600] "
               "[--every N] [--sensors] [--trails] [--video FILE.mp4] [--fps 30] [--html FILE.html] [--force]\n"
               "       duel_evolve render-net BLOB --out FILE.png [--force] [--min-weight W]\n"
               "       duel_evolve export BLOB --c-array NAME [-o FILE.c] [--header FILE.h] [--force]\n"
               "A and B: champion blobs or genome files (champions/gen-N.blob, .genome) or builtin:NAME; wherever a BLOB "
               "is named, a genome file may be. Robot duels in world v%d unless a run or --world names another (docs/duel-world.md). Under mpirun, run, resume and experiment use every rank "
               "(docs/cluster.md)%s.\n", DUEL_SPEC_VERSION, duel_mpi_built() ? "" : "; this build has no MPI");
}

typedef struct duel_command {
    const char *name;
    int (*run)(int argc, char **argv);
} duel_command;

static const duel_command duel_commands[] = {
    {"run", duel_cmd_run},         {"resume", duel_cmd_resume},   {"config", duel_cmd_config},
    {"ladder", duel_cmd_ladder},   {"play", duel_cmd_play},       {"inspect", duel_cmd_inspect},
    {"compare", duel_cmd_compare}, {"experiment", duel_cmd_experiment},
    {"dot", duel_cmd_dot},         {"node", duel_cmd_node},       {"log", duel_cmd_log},
    {"render", duel_cmd_render},   {"render-net", duel_cmd_render_net}, {"export", duel_cmd_export},
    {"report", duel_cmd_report},
};

/* What a command printed must have reached standard output: a full disk or
 * a closed pipe (`> /dev/full`) is a failure, whatever the command thought. */
static int duel_stdout_status(const char *cmd, int rc)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        /* a command that failed already said why; one that wrote to a failing stdout did not */
        int e = errno;
        if (rc != 0 && rc != 1)
            return rc;
        fprintf(stderr, "duel_evolve: %s: cannot write standard output: %s\n", cmd, strerror(e ? e : EIO));
        return 1;
    }
    return rc;
}

/* argv[0] a subcommand: runs it (an MPI rank executes an experiment's tasks through this). */
static int duel_dispatch(int argc, char **argv)
{
    size_t i;
    for (i = 0; i < sizeof duel_commands / sizeof duel_commands[0]; i++)
        if (strcmp(argv[0], duel_commands[i].name) == 0)
            return duel_commands[i].run(argc - 1, argv + 1);
    fprintf(stderr, "duel_evolve: unknown command '%s'\n", duel_esc(argv[0]));
    return 2;
}

int duel_evolve_main(int argc, char **argv)
{
    size_t i;
    int rc;
    duel_html_set_generator("neat-duel " DUEL_VERSION); /* what the web pages name as their maker (the package says the same) */
    rc = duel_mpi_start(argc - 1, argv + 1);
    if (rc != 0)
        return duel_mpi_finish(rc);
    if (duel_mpi_size() > 1) {
        /* under mpirun: rank 0 runs the command, the others do what it hands them */
        int spread = argc >= 2 && (strcmp(argv[1], "run") == 0 || strcmp(argv[1], "resume") == 0 ||
                                   strcmp(argv[1], "experiment") == 0);
        if (!spread) {
            if (duel_mpi_rank() == 0)
                fprintf(stderr, "duel_evolve: %s runs in one process: under mpirun only run, resume and experiment "
                                "spread their work over the ranks\n", argc >= 2 ? argv[1] : "(no command)");
            return duel_mpi_finish(2);
        }
        if (duel_mpi_rank() != 0)
            return duel_mpi_finish(duel_mpi_serve(argc - 1, argv + 1, duel_dispatch));
    }
    if (argc >= 2 && strcmp(argv[1], "--version") == 0) {
        /* the project's version (CMakeLists.txt) and the formats this build reads and writes */
        printf("duel_evolve %s (duel world v%d %016llx by default, blob formats %d-%d, checkpoint format %d)\n",
               DUEL_VERSION, DUEL_SPEC_VERSION, (unsigned long long)duel_rules_id(duel_rules_v1()), NRT_FORMAT_VERSION,
               NRT_FORMAT_VERSION_PROPAGATE, NEAT_CHECKPOINT_VERSION);
        return duel_mpi_finish(duel_stdout_status("--version", 0));
    }
    if (argc < 2 || strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        duel_usage(argc < 2 ? stderr : stdout);
        return duel_mpi_finish(duel_stdout_status("--help", argc < 2 ? 2 : 0));
    }
    for (i = 0; i < sizeof duel_commands / sizeof duel_commands[0]; i++)
        if (strcmp(argv[1], duel_commands[i].name) == 0) {
            /* COMMAND ... --help: its options on stdout, nothing run */
            if (duel_help_wanted(argc - 2, argv + 2) && duel_help(argv[1], stdout) == 0)
                return duel_mpi_finish(duel_stdout_status(argv[1], 0));
            return duel_mpi_finish(duel_stdout_status(argv[1], duel_commands[i].run(argc - 2, argv + 2)));
        }
    fprintf(stderr, "duel_evolve: unknown command '%s'\n", duel_esc(argv[1]));
    duel_usage(stderr);
    return duel_mpi_finish(2);
}
