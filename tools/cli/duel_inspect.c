/* duel_inspect.c - `duel_evolve inspect BLOB|GENOME` and `duel_evolve dot BLOB|GENOME`: a champion's genes and network as text or Graphviz (a run directory or checkpoint goes to duel_inspect_run.c). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "duel_cli.h"
#include "duel_ctrl.h"
#include "duel_files.h"
#include "neat_config.h"

/* Names of the duel's inputs (docs/duelsim.md, sensors in the spec's order;
 * rangefinder sector k is centred on heading + k * 72 degrees counter-clockwise)
 * and outputs. Networks of other sizes get generic names. */
static const char *const duel_insp_inputs[DUEL_N_INPUTS] = {
    "bias",           "food_ahead",  "food_left",       "food_back_left",   "food_back_right",
    "food_right",     "robot_ahead", "robot_left",      "robot_back_left",  "robot_back_right",
    "robot_right",    "energy_diff", "wall"};
static const char *const duel_insp_outputs[DUEL_N_OUTPUTS] = {"turn_left", "turn_right", "forward"};

#define DUEL_INSP_NAME 24 /* longest node name, with its terminator */

/* A loaded blob and what both commands derive from it. */
typedef struct duel_insp {
    const char *path;
    uint8_t *blob;
    size_t len;
    void *mem;
    size_t mem_required;
    nrt_net net;
    uint16_t *dst;       /* [n_conns] target node of each connection */
    uint8_t *recurrent;  /* [n_conns] 1 if the connection lies on a directed cycle */
    uint8_t *upward;     /* [n_conns] 1 if it may set the drawing's ranks (dot only) */
    unsigned n_recurrent;
    int duel_names;      /* 13 inputs and 3 outputs: the duel's sensor and motor names */
    uint32_t n_in[NRT_MAX_NODES], n_out[NRT_MAX_NODES]; /* connections into and out of each node */
} duel_insp;

/* Tarjan's strongly connected components over the network's nodes (a DFS;
 * depth at most NRT_MAX_NODES). */
typedef struct duel_insp_scc {
    duel_insp *x;
    const uint32_t *first; /* [n_nodes + 1] outgoing connections of node v: by_src[first[v] .. first[v+1]) */
    const uint32_t *by_src;
    int index[NRT_MAX_NODES], low[NRT_MAX_NODES], comp[NRT_MAX_NODES];
    uint8_t on_stack[NRT_MAX_NODES], seen[NRT_MAX_NODES];
    uint16_t stack[NRT_MAX_NODES];
    int sp, next_index, n_comp;
} duel_insp_scc;

static void duel_insp_scc_visit(duel_insp_scc *s, unsigned v)
{
    uint32_t e;
    s->index[v] = s->low[v] = s->next_index++;
    s->stack[s->sp++] = (uint16_t)v;
    s->on_stack[v] = 1;
    for (e = s->first[v]; e < s->first[v + 1]; e++) {
        unsigned w = s->x->dst[s->by_src[e]];
        if (s->index[w] < 0) {
            duel_insp_scc_visit(s, w);
            if (s->low[w] < s->low[v])
                s->low[v] = s->low[w];
        } else if (s->on_stack[w] && s->index[w] < s->low[v]) {
            s->low[v] = s->index[w];
        }
    }
    if (s->low[v] == s->index[v]) {
        unsigned w;
        do {
            w = s->stack[--s->sp];
            s->on_stack[w] = 0;
            s->comp[w] = s->n_comp;
        } while (w != v);
        s->n_comp++;
    }
}

/* For the drawing's ranks: a DFS from the inputs in index order along the
 * connections that do not leave an output; those reaching back to a node
 * still on the DFS path are left out, so the rest form a DAG from inputs to
 * outputs (each such back edge is recurrent). */
static void duel_insp_rank_visit(duel_insp_scc *s, unsigned v)
{
    duel_insp *x = s->x;
    uint32_t e;
    int is_output = v >= x->net.n_inputs && v < (unsigned)(x->net.n_inputs + x->net.n_outputs);
    s->seen[v] = 1; /* on the path */
    for (e = s->first[v]; e < s->first[v + 1] && !is_output; e++) {
        uint32_t k = s->by_src[e];
        unsigned w = x->dst[k];
        x->upward[k] = s->seen[w] != 1;
        if (s->seen[w] == 0)
            duel_insp_rank_visit(s, w);
    }
    s->seen[v] = 2; /* done */
}

/* Marks the recurrent connections: source and target in one strongly
 * connected component, i.e. the target reaches the source again (a self
 * loop included). Independent of node or connection order. Also marks the
 * upward connections the drawing ranks by. Returns 0 or -1 (out of memory). */
static int duel_insp_recurrence(duel_insp *x)
{
    const nrt_net *n = &x->net;
    duel_insp_scc *s = (duel_insp_scc *)calloc(1, sizeof *s);
    uint32_t *first = (uint32_t *)calloc(n->n_nodes + 1u, sizeof *first);
    uint32_t *by_src = (uint32_t *)malloc((n->n_conns + 1u) * sizeof *by_src);
    uint32_t k, fill[NRT_MAX_NODES];
    unsigned v;

    if (s == NULL || first == NULL || by_src == NULL) {
        free(s);
        free(first);
        free(by_src);
        return -1;
    }
    for (k = 0; k < n->n_conns; k++)
        first[n->src[k] + 1]++;
    for (v = 0; v < n->n_nodes; v++) {
        first[v + 1] += first[v];
        fill[v] = first[v];
    }
    for (k = 0; k < n->n_conns; k++)
        by_src[fill[n->src[k]]++] = k;
    s->x = x;
    s->first = first;
    s->by_src = by_src;
    for (v = 0; v < n->n_nodes; v++)
        s->index[v] = -1;
    for (v = 0; v < n->n_nodes; v++)
        if (s->index[v] < 0)
            duel_insp_scc_visit(s, v);
    for (v = 0; v < n->n_nodes; v++)
        if (!s->seen[v])
            duel_insp_rank_visit(s, v);
    x->n_recurrent = 0;
    for (k = 0; k < n->n_conns; k++) {
        x->recurrent[k] = s->comp[n->src[k]] == s->comp[x->dst[k]];
        x->n_recurrent += x->recurrent[k];
    }
    free(s);
    free(first);
    free(by_src);
    return 0;
}

static void duel_insp_free(duel_insp *x)
{
    free(x->blob);
    free(x->mem);
    free(x->dst);
    free(x->recurrent);
    free(x->upward);
    memset(x, 0, sizeof *x);
}

/* Reads and validates the blob at path; on error prints one line and
 * returns -1. */
static int duel_insp_open(duel_insp *x, const char *path)
{
    nrt_net *n = &x->net;
    uint32_t k;
    unsigned j;
    int err;

    memset(x, 0, sizeof *x);
    x->path = path;
    if (duel_cli_read_blob(path, &x->blob, &x->len) != 0)
        return -1;
    err = nrt_mem_required(x->blob, x->len, &x->mem_required);
    if (!err) {
        x->mem = malloc(x->mem_required);
        err = x->mem == NULL ? NRT_E_NOMEM : nrt_load(n, x->blob, x->len, x->mem, x->mem_required);
    }
    if (err) {
        fprintf(stderr, "duel_evolve: %s: not a valid champion blob: %s\n", path, nrt_strerror(err));
        duel_insp_free(x);
        return -1;
    }
    x->dst = (uint16_t *)malloc((n->n_conns + 1u) * sizeof *x->dst);
    x->recurrent = (uint8_t *)malloc(n->n_conns + 1u);
    x->upward = (uint8_t *)calloc(n->n_conns + 1u, 1);
    if (x->dst == NULL || x->recurrent == NULL || x->upward == NULL) {
        fprintf(stderr, "duel_evolve: %s: out of memory\n", path);
        duel_insp_free(x);
        return -1;
    }
    /* the connections into non-input node j end at end[j], start where j-1's end */
    for (j = 0, k = 0; j < (unsigned)(n->n_nodes - n->n_inputs); j++)
        for (; k < n->end[j]; k++)
            x->dst[k] = (uint16_t)(n->n_inputs + j);
    for (k = 0; k < n->n_conns; k++) {
        x->n_out[n->src[k]]++;
        x->n_in[x->dst[k]]++;
    }
    if (duel_insp_recurrence(x) != 0) {
        fprintf(stderr, "duel_evolve: %s: out of memory\n", path);
        duel_insp_free(x);
        return -1;
    }
    x->duel_names = n->n_inputs == DUEL_N_INPUTS && n->n_outputs == DUEL_N_OUTPUTS;
    return 0;
}

static const char *duel_insp_kind(const duel_insp *x, unsigned v)
{
    if (v == 0)
        return "bias";
    if (v < x->net.n_inputs)
        return "input";
    return v < (unsigned)(x->net.n_inputs + x->net.n_outputs) ? "output" : "hidden";
}

/* Node v's name: the duel's sensor or motor name, else bias, inK, outK; hK
 * for hidden node index K. */
static const char *duel_insp_name(const duel_insp *x, unsigned v, char buf[DUEL_INSP_NAME])
{
    unsigned n_in = x->net.n_inputs, n_out = x->net.n_outputs;
    if (v == 0)
        return "bias";
    if (v < n_in) {
        if (x->duel_names)
            return duel_insp_inputs[v];
        snprintf(buf, DUEL_INSP_NAME, "in%u", v);
    } else if (v < n_in + n_out) {
        if (x->duel_names)
            return duel_insp_outputs[v - n_in];
        snprintf(buf, DUEL_INSP_NAME, "out%u", v - n_in);
    } else {
        snprintf(buf, DUEL_INSP_NAME, "h%u", v);
    }
    return buf;
}

static uint32_t duel_insp_rd32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

/* ---- inspect ------------------------------------------------------------ */

/* A run directory, or a file that starts like a coevolution checkpoint. */
static int duel_is_checkpoint(const char *path)
{
    struct stat st;
    char magic[8];
    FILE *f;
    int yes;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        return 1;
    f = fopen(path, "rb");
    if (f == NULL)
        return 0;
    yes = fread(magic, 1, 8, f) == 8 && memcmp(magic, "NEATCOEV", 8) == 0;
    fclose(f);
    return yes;
}

/* A genome file's own content, before its network's: the shape, every
 * node gene and every connection gene (innovation, enabled, the exact
 * double weight), and the fitness it was saved with. */
static int duel_inspect_genome(const char *path)
{
    neat_genome g;
    uint32_t ni, no, i, disabled = 0;
    if (duel_genome_read(path, &g, &ni, &no) != 0)
        return -1;
    for (i = 0; i < g.n_conns; i++)
        disabled += !g.conns[i].enabled;
    printf("genome file: %s\n", path);
    printf("genome format version: %u\n", (unsigned)NEAT_GENOME_FILE_VERSION);
    printf("genome inputs: %u (bias not included)\n", (unsigned)ni);
    printf("genome outputs: %u\n", (unsigned)no);
    printf("node genes: %u (%u hidden)\n", (unsigned)g.n_nodes, (unsigned)neat_genome_hidden_count(&g));
    printf("connection genes: %u (%u disabled)\n", (unsigned)g.n_conns, (unsigned)disabled);
    if (g.has_fitness) {
        char num[NEAT_FMT_DOUBLE];
        neat_fmt_double(num, g.fitness);
        printf("fitness: %s\n", num);
    } else
        printf("fitness: none\n");
    printf("node genes (id, type):\n");
    for (i = 0; i < g.n_nodes; i++) {
        static const char *const kind[] = {"bias", "input", "output", "hidden"};
        printf("gene node %5lu  %s\n", (unsigned long)g.nodes[i].id,
               g.nodes[i].type <= 3 ? kind[g.nodes[i].type] : "?");
    }
    printf("connection genes (innovation, in -> out, weight, enabled):\n");
    for (i = 0; i < g.n_conns; i++) {
        char num[NEAT_FMT_DOUBLE];
        neat_fmt_double(num, g.conns[i].weight);
        printf("gene conn %6lu  %5lu -> %5lu  weight %s%s\n", (unsigned long)g.conns[i].innov,
               (unsigned long)g.conns[i].in, (unsigned long)g.conns[i].out, num,
               g.conns[i].enabled ? "" : "  disabled");
    }
    printf("its network, as the runtime runs it (the blob it encodes to):\n");
    neat_genome_free(&g, NULL);
    return 0;
}

/* whether the file at path starts as a genome file does */
static int duel_is_genome_path(const char *path)
{
    uint8_t magic[8];
    FILE *f = fopen(path, "rb");
    int yes;
    if (f == NULL)
        return 0;
    yes = fread(magic, 1, 8, f) == 8 && duel_is_genome_file(magic, 8);
    fclose(f);
    return yes;
}

int duel_cmd_inspect(int argc, char **argv)
{
    duel_insp x;
    const nrt_net *n;
    unsigned v;
    uint32_t k;
    int rc = 0;

    if (argc != 1 || argv[0][0] == '-') {
        fprintf(stderr, "usage: duel_evolve inspect BLOB | GENOME | RUN_DIR | CHECKPOINT\n");
        return 2;
    }
    if (duel_is_checkpoint(argv[0]))
        return duel_inspect_run(argv[0]);
    if (duel_is_genome_path(argv[0]) && duel_inspect_genome(argv[0]) != 0)
        return 2;
    if (duel_insp_open(&x, argv[0]) != 0)
        return 2;
    n = &x.net;
    printf("file: %s\n", x.path);
    printf("size: %lu bytes\n", (unsigned long)x.len);
    printf("crc32: 0x%08lx\n", (unsigned long)duel_insp_rd32(x.blob + NRT_OFF_CRC));
    printf("format version: %u\n", (unsigned)(x.blob[NRT_OFF_VERSION] | (x.blob[NRT_OFF_VERSION + 1] << 8)));
    printf("inputs: %u (bias included)\n", (unsigned)n->n_inputs);
    printf("outputs: %u\n", (unsigned)n->n_outputs);
    printf("hidden: %u\n", (unsigned)n->n_hidden);
    printf("connections: %u\n", (unsigned)n->n_conns);
    printf("recurrent: %u (on a directed cycle, self-loops included)\n", x.n_recurrent);
    printf("ram: %lu bytes (nrt_mem_required)\n", (unsigned long)x.mem_required);
    printf("names: %s\n", x.duel_names ? "duel sensors and motors" : "generic (not the duel's 13 inputs and 3 outputs)");
    printf("nodes (index, kind, name, connections in and out):\n");
    for (v = 0; v < n->n_nodes; v++) {
        char buf[DUEL_INSP_NAME];
        printf("node %3u  %-6s  %-16s  in %3lu  out %3lu\n", v, duel_insp_kind(&x, v), duel_insp_name(&x, v, buf),
               (unsigned long)x.n_in[v], (unsigned long)x.n_out[v]);
    }
    printf("connections (index, source -> target, weight, raw Q3.12):\n");
    for (k = 0; k < n->n_conns; k++) {
        char b1[DUEL_INSP_NAME], b2[DUEL_INSP_NAME];
        printf("conn %4lu  %-16s -> %-16s  weight %7.4f  raw %6d%s\n", (unsigned long)k,
               duel_insp_name(&x, n->src[k], b1), duel_insp_name(&x, x.dst[k], b2),
               n->weight[k] / 4096.0, (int)n->weight[k], x.recurrent[k] ? "  recurrent" : "");
    }
    duel_insp_free(&x);
    return rc;
}

/* ---- dot ------------------------------------------------------------------ */

/* s as the inside of a DOT string: quotes and backslashes escaped, control
 * characters replaced. */
static void duel_dot_str(FILE *f, const char *s)
{
    for (; *s != '\0'; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fputc('\\', f);
        fputc(c < 0x20 || c == 0x7f ? '?' : c, f);
    }
}

static void duel_dot_write(FILE *f, const duel_insp *x)
{
    const nrt_net *n = &x->net;
    unsigned v, n_io = (unsigned)(n->n_inputs + n->n_outputs);
    uint32_t k;
    char buf[DUEL_INSP_NAME];

    fprintf(f, "/* duel_evolve dot: a champion network (docs/tools.md) */\ndigraph champion {\n");
    fprintf(f, "  rankdir=BT;\n  nodesep=0.2;\n  ranksep=0.6;\n");
    fprintf(f, "  graph [labelloc=t, fontname=\"Helvetica\", fontsize=14, label=\"");
    duel_dot_str(f, x->path);
    fprintf(f, ": %u inputs (bias included), %u outputs, %u hidden, %u connections (%u recurrent)\\n"
               "black: positive weight, red: negative; pen width 0.5 + 2.5 |w| / 8; "
               "dashed: recurrent; grey: unused input\"];\n",
            (unsigned)n->n_inputs, (unsigned)n->n_outputs, (unsigned)n->n_hidden, (unsigned)n->n_conns,
            x->n_recurrent);
    fprintf(f, "  node [fontname=\"Helvetica\", fontsize=10];\n  edge [arrowsize=0.6];\n");

    /* inputs in one rank at the bottom, in sensor order (invisible flat edges) */
    fprintf(f, "  subgraph inputs {\n    rank=source;\n");
    for (v = 0; v < n->n_inputs; v++)
        fprintf(f, "    n%u [label=\"%s\", shape=box%s];\n", v, duel_insp_name(x, v, buf),
                x->n_out[v] == 0 ? ", color=gray70, fontcolor=gray70" : "");
    if (n->n_inputs > 1) {
        fprintf(f, "    ");
        for (v = 0; v < n->n_inputs; v++)
            fprintf(f, "n%u%s", v, v + 1 < n->n_inputs ? " -> " : " [style=invis];\n");
    }
    fprintf(f, "  }\n");

    /* outputs in one rank at the top */
    fprintf(f, "  subgraph outputs {\n    rank=sink;\n");
    for (v = n->n_inputs; v < n_io; v++)
        fprintf(f, "    n%u [label=\"%s\", shape=box, style=bold];\n", v, duel_insp_name(x, v, buf));
    if (n->n_outputs > 1) {
        fprintf(f, "    ");
        for (v = n->n_inputs; v < n_io; v++)
            fprintf(f, "n%u%s", v, v + 1 < n_io ? " -> " : " [style=invis];\n");
    }
    fprintf(f, "  }\n");

    for (v = n_io; v < n->n_nodes; v++)
        fprintf(f, "  n%u [label=\"%s\", shape=circle, width=0.3, fixedsize=false];\n", v,
                duel_insp_name(x, v, buf));

    /* one edge per connection; only the upward ones (a DAG) set the ranks */
    for (k = 0; k < n->n_conns; k++) {
        int w = n->weight[k];
        unsigned s = n->src[k];
        int free_rank = !x->upward[k];
        fprintf(f, "  n%u -> n%u [penwidth=%.2f, color=%s, tooltip=\"%.4f\"%s%s];\n", s, (unsigned)x->dst[k],
                0.5 + 2.5 * (w < 0 ? -w : w) / 4096.0 / 8.0, w < 0 ? "red" : "black", w / 4096.0,
                x->recurrent[k] ? ", style=dashed" : "", free_rank ? ", constraint=false" : "");
    }
    fprintf(f, "}\n");
}

int duel_dot_blob(FILE *f, const char *path)
{
    duel_insp x;
    if (duel_insp_open(&x, path) != 0)
        return -1;
    duel_dot_write(f, &x);
    duel_insp_free(&x);
    return 0;
}

/* duel_file_write_with's callback */
static void duel_dot_write_cb(FILE *f, const void *ctx)
{
    duel_dot_write(f, (const duel_insp *)ctx);
}

int duel_cmd_dot(int argc, char **argv)
{
    duel_insp x;
    const char *blob = NULL, *out = NULL;
    int i, rc = 0;

    for (i = 0; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "duel_evolve: dot: -o needs a file name\n");
                return 2;
            }
            out = argv[++i];
        } else if (argv[i][0] == '-' || blob != NULL) {
            fprintf(stderr, "usage: duel_evolve dot BLOB [-o FILE.dot]\n");
            return 2;
        } else {
            blob = argv[i];
        }
    }
    if (blob == NULL) {
        fprintf(stderr, "usage: duel_evolve dot BLOB [-o FILE.dot]\n");
        return 2;
    }
    if (duel_insp_open(&x, blob) != 0)
        return 2;
    if (out != NULL) {
        rc = duel_file_write_with(out, duel_dot_write_cb, &x);
    } else {
        duel_dot_write(stdout, &x); /* a failing stdout: duel_evolve.c says so */
    }
    duel_insp_free(&x);
    return rc;
}
