/* duel_mpi.c - the MPI job: started only under mpirun, every rank's build checked against rank 0's, ranks released at the end, messages counted. */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "duel.h"
#include "duel_cores.h"
#include "duel_mpi_internal.h"
#include "duel_text.h"
#include "neat.h"
#include "neat_coev.h"
#include "nrt.h"

#ifndef DUEL_VERSION
#define DUEL_VERSION "0"
#endif
/* The protocol of this directory's messages; a test build sets another salt to play a mismatched rank. */
#define DUEL_MPI_PROTOCOL 2 /* 2: the work header carries the rules of the world */
#ifndef DUEL_MPI_SALT
#define DUEL_MPI_SALT 0
#endif

duel_mpi_job duel_mpi_g = {0, 0, 1, NULL, 0, 0, 0, 0, {0, 0, 0, 0, 0}};

int duel_mpi_built(void)
{
    return 1;
}

uint32_t duel_mpi_rank(void)
{
    return (uint32_t)duel_mpi_g.rank;
}

uint32_t duel_mpi_size(void)
{
    return (uint32_t)duel_mpi_g.size;
}

static uint64_t duel_fnv(uint64_t h, const void *p, size_t n)
{
    const uint8_t *b = (const uint8_t *)p;
    size_t i;
    for (i = 0; i < n; i++) {
        h ^= b[i];
        h *= 1099511628211ull;
    }
    return h;
}

/* Two ranks may work together only if they play every game alike: the same versions and formats, the same byte
 * order and sizes, and one game of the duel played here to the same result (a different compiler or build of the
 * same version that moved a robot differently shows there). */
static uint64_t duel_mpi_version_word(void)
{
    char text[256];
    uint64_t h = 14695981039346656037ull;
    uint32_t one = 1;
    duel_controller w, e;
    duel_result res;
    snprintf(text, sizeof text, "neat-duel %s; mpi protocol %d salt %d; world v1 %016llx; checkpoint %d/%d; blob %d; "
                                "runtime %d.%d; pointer %u; int %u",
             DUEL_VERSION, DUEL_MPI_PROTOCOL, DUEL_MPI_SALT, (unsigned long long)duel_rules_id(duel_rules_v1()),
             NEAT_CHECKPOINT_VERSION,
             NEAT_COEV_CHECKPOINT_VERSION, NRT_FORMAT_VERSION, NRT_VERSION_MAJOR, NRT_VERSION_MINOR,
             (unsigned)sizeof(void *), (unsigned)sizeof(int));
    h = duel_fnv(h, text, strlen(text));
    h = duel_fnv(h, &one, sizeof one); /* byte order */
    memset(&w, 0, sizeof w);
    memset(&e, 0, sizeof e);
    w.builtin = duel_builtin_parse("forager");
    e.builtin = duel_builtin_parse("hunter");
    memset(&res, 0, sizeof res);
    if (duel_play(&w, &e, 3, &res, NULL, NULL) == 0) {
        h = duel_fnv(h, &res.outcome, sizeof res.outcome);
        h = duel_fnv(h, &res.steps, sizeof res.steps);
        h = duel_fnv(h, res.energy, sizeof res.energy);
    }
    return h;
}

/* Started by mpirun, srun or another launcher that sets its rank in the environment (and not a child process of
 * an experiment, which plays alone: DUEL_MPI=0). */
static int duel_mpi_launched(void)
{
    static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"};
    const char *off = getenv("DUEL_MPI");
    size_t i;
    if (off != NULL && strcmp(off, "0") == 0)
        return 0;
    for (i = 0; i < sizeof vars / sizeof vars[0]; i++)
        if (getenv(vars[i]) != NULL)
            return 1;
    return 0;
}

/* --threads T of the command line, 0 if not given (or not a number: the command refuses it later). */
static uint32_t duel_mpi_threads_arg(int argc, char **argv)
{
    int i;
    for (i = 0; i + 1 < argc; i++)
        if (strcmp(argv[i], "--threads") == 0) {
            char *end;
            unsigned long v = strtoul(argv[i + 1], &end, 10);
            return *end == '\0' && v <= 256 ? (uint32_t)v : 0;
        }
    return 0;
}

uint32_t duel_mpi_default_threads(void)
{
    uint32_t cores = duel_cores();
    uint32_t local = duel_mpi_g.active && duel_mpi_g.peers != NULL ? duel_mpi_g.peers[duel_mpi_g.rank].local : 1;
    uint32_t t = cores / (local ? local : 1);
    return t ? t : 1;
}

int duel_mpi_start(int argc, char **argv)
{
    duel_mpi_peer me, *all;
    MPI_Comm node;
    int provided = 0, local = 1, r, bad = -1;
    if (!duel_mpi_launched())
        return 0;
    {
        /* every rank reads the same environment (mpirun -x): each refuses it alike, before MPI starts */
        double w;
        if (duel_mpi_wait_parse(&w) != 0) {
            char esc[300];
            fprintf(stderr, "duel_evolve: mpi: DUEL_MPI_WAIT='%s': expected seconds, a number above 0 and at most "
                            "1000000 (60 when unset)\n", duel_text_escape(getenv("DUEL_MPI_WAIT"), esc, sizeof esc));
            return 2;
        }
    }
    if (MPI_Init_thread(NULL, NULL, MPI_THREAD_MULTIPLE, &provided) != MPI_SUCCESS) {
        fprintf(stderr, "duel_evolve: mpi: MPI_Init failed\n");
        return 1;
    }
    duel_mpi_g.active = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &duel_mpi_g.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &duel_mpi_g.size);
    duel_mpi_g.games_comm = MPI_COMM_WORLD;
    if (MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node) == MPI_SUCCESS) {
        MPI_Comm_size(node, &local);
        MPI_Comm_free(&node);
    }
    memset(&me, 0, sizeof me);
    me.version = duel_mpi_version_word();
    me.local = (uint32_t)local;
    me.beats = provided >= MPI_THREAD_MULTIPLE;
    if (gethostname(me.host, sizeof me.host - 1) != 0)
        strcpy(me.host, "?");
    all = (duel_mpi_peer *)calloc((size_t)duel_mpi_g.size, sizeof *all);
    if (all == NULL) {
        fprintf(stderr, "duel_evolve: mpi: out of memory\n");
        MPI_Abort(MPI_COMM_WORLD, 1);
        return 1;
    }
    duel_mpi_g.peers = all;
    all[duel_mpi_g.rank] = me;
    me.threads = duel_mpi_threads_arg(argc, argv);
    if (me.threads == 0)
        me.threads = duel_mpi_default_threads();
    MPI_Allgather(&me, (int)sizeof me, MPI_BYTE, all, (int)sizeof me, MPI_BYTE, MPI_COMM_WORLD);
    for (r = 1; r < duel_mpi_g.size && bad < 0; r++)
        if (all[r].version != all[0].version)
            bad = r;
    if (bad >= 0) {
        duel_mpi_g.quiet_end = 1;
        if (duel_mpi_g.rank == 0)
            fprintf(stderr, "duel_evolve: mpi: rank %d (on %s) runs another build of duel_evolve than rank 0 (on %s): "
                            "version word %016llx, not %016llx; install the same build on every machine\n",
                    bad, all[bad].host, all[0].host, (unsigned long long)all[bad].version,
                    (unsigned long long)all[0].version);
        return 2;
    }
    if (provided < MPI_THREAD_FUNNELED) {
        duel_mpi_g.quiet_end = 1;
        if (duel_mpi_g.rank == 0)
            fprintf(stderr, "duel_evolve: mpi: this MPI library gives no thread support (MPI_THREAD_FUNNELED): "
                            "the ranks could not play on threads\n");
        return 2;
    }
    if (duel_mpi_alive_start(provided) != 0) {
        fprintf(stderr, "duel_evolve: mpi: rank %d cannot start its signs of life: out of memory or threads\n",
                duel_mpi_g.rank);
        MPI_Abort(MPI_COMM_WORLD, 1);
        return 1;
    }
    return 0;
}

void duel_mpi_nap(long usec)
{
    struct timespec ts;
    ts.tv_sec = usec / 1000000L;
    ts.tv_nsec = (usec % 1000000L) * 1000L;
    nanosleep(&ts, NULL);
}

int duel_mpi_recv(MPI_Comm comm, int src, int tag, uint8_t **buf, size_t *len, MPI_Status *st)
{
    long nap = 5, napped = 0;
    int flag = 0, count = 0, world_src = src;
    MPI_Status s;
    MPI_Message msg;
    if (src != MPI_ANY_SOURCE && comm != MPI_COMM_WORLD) {
        /* whose signs of life to watch: src's rank in the world */
        MPI_Group g, w;
        MPI_Comm_group(comm, &g);
        MPI_Comm_group(MPI_COMM_WORLD, &w);
        MPI_Group_translate_ranks(g, 1, &src, w, &world_src);
        MPI_Group_free(&g);
        MPI_Group_free(&w);
    }
    for (;;) {
        /* a matched probe: the signs-of-life thread takes messages from this communicator too */
        if (MPI_Improbe(src, tag, comm, &flag, &msg, &s) != MPI_SUCCESS)
            return -1;
        if (flag && comm == MPI_COMM_WORLD && s.MPI_TAG == DUEL_TAG_ALIVE && tag != DUEL_TAG_ALIVE) {
            MPI_Mrecv(NULL, 0, MPI_BYTE, &msg, MPI_STATUS_IGNORE);
            duel_mpi_alive_heard(s.MPI_SOURCE);
            continue;
        }
        if (flag)
            break;
        duel_mpi_nap(nap);
        napped += nap;
        if (nap < 1000)
            nap *= 2; /* 5 us at first (a reply on its way), at most 1 ms (rank 0 between generations) */
        if (napped >= 1000000L && world_src != MPI_ANY_SOURCE) {
            napped = 0;
            duel_mpi_alive_check(world_src, "a message from it");
        }
    }
    MPI_Get_count(&s, MPI_BYTE, &count);
    *buf = (uint8_t *)malloc(count > 0 ? (size_t)count : 1u);
    if (*buf == NULL)
        return -1;
    if (MPI_Mrecv(*buf, count, MPI_BYTE, &msg, st) != MPI_SUCCESS) {
        free(*buf);
        *buf = NULL;
        return -1;
    }
    *len = (size_t)count;
    duel_mpi_g.stats.recv_msgs++;
    duel_mpi_g.stats.recv_bytes += (uint64_t)count;
    return 0;
}

int duel_mpi_send(MPI_Comm comm, int dst, int tag, const void *buf, size_t len)
{
    if (len > (size_t)0x7fffffff)
        return -1;
    if (MPI_Send(buf, (int)len, MPI_BYTE, dst, tag, comm) != MPI_SUCCESS)
        return -1;
    duel_mpi_g.stats.sent_msgs++;
    duel_mpi_g.stats.sent_bytes += len;
    return 0;
}

int duel_mpi_serve(int argc, char **argv, int (*command)(int argc, char **argv))
{
    uint32_t threads = duel_mpi_g.peers[duel_mpi_g.rank].threads;
    int status = 0;
    /* what a rank would print is rank 0's to print: the tasks' tables and lines go nowhere (errors still
     * reach stderr) */
    if (freopen("/dev/null", "w", stdout) == NULL)
        return 1;
    /* Ctrl-C reaches every rank (mpirun forwards it): rank 0 finishes the generation in flight, saves it and
     * releases the others, who must play that generation's games to the end for it */
    signal(SIGINT, SIG_IGN);
    signal(SIGTERM, SIG_IGN);
    if (argc >= 1 && strcmp(argv[0], "experiment") == 0)
        return duel_mpi_exp_serve(threads, command);
    if (argc >= 1 && (strcmp(argv[0], "run") == 0 || strcmp(argv[0], "resume") == 0)) {
        if (duel_mpi_games_serve(MPI_COMM_WORLD, 0, threads, &status) != 0) {
            fprintf(stderr, "duel_evolve: mpi: rank %d lost rank 0\n", duel_mpi_g.rank);
            return 1;
        }
        return status;
    }
    return 2; /* rank 0 says why */
}

int duel_mpi_finish(int rc)
{
    if (!duel_mpi_g.active)
        return rc;
    duel_mpi_alive_stop();
    if (duel_mpi_g.rank == 0 && !duel_mpi_g.quiet_end) {
        int r;
        int32_t st = rc;
        for (r = 1; r < duel_mpi_g.size; r++)
            duel_mpi_send(MPI_COMM_WORLD, r, DUEL_TAG_END, &st, sizeof st);
    }
    MPI_Finalize();
    free(duel_mpi_g.peers);
    duel_mpi_g.peers = NULL;
    duel_mpi_g.active = 0;
    return rc;
}

int duel_mpi_stop_requested(void)
{
    int flag = 0;
    MPI_Status st;
    if (!duel_mpi_g.active || !duel_mpi_g.in_task)
        return 0;
    if (!duel_mpi_g.stop_asked && MPI_Iprobe(0, DUEL_TAG_INT, MPI_COMM_WORLD, &flag, &st) == MPI_SUCCESS && flag) {
        uint8_t b[8];
        MPI_Recv(b, (int)sizeof b, MPI_BYTE, 0, DUEL_TAG_INT, MPI_COMM_WORLD, &st);
        duel_mpi_g.stop_asked = 1;
    }
    return duel_mpi_g.stop_asked;
}
