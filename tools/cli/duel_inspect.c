/* duel_inspect.c - `duel_evolve inspect BLOB|GENOME` and `duel_evolve dot BLOB|GENOME`: a champion's genes and network as text or Graphviz (a run directory or checkpoint goes to duel_inspect_run.c). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "duel_cli.h"
#include "duel_text.h"
#include "duel_ctrl.h"
#include "duel_files.h"
#include "duel_outputs.h"
#include "duel_netgraph.h"
#include "neat_config.h"

#define DUEL_DOT_ROW 6     /* hidden nodes in a row of the drawing at most */

/* A loaded blob and its graph (duel_netgraph.h). */
typedef struct duel_insp {
    const char *path;
    uint8_t *blob;
    size_t len;
    void *mem;
    size_t mem_required;
    nrt_net net;
    duel_netgraph g;
} duel_insp;

static void duel_insp_free(duel_insp *x)
{
    free(x->blob);
    free(x->mem);
    duel_netgraph_free(&x->g);
    memset(x, 0, sizeof *x);
}

/* Reads and validates the blob at path; on error prints one line and
 * returns -1. */
static int duel_insp_open(duel_insp *x, const char *path)
{
    nrt_net *n = &x->net;
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
        fprintf(stderr, "duel_evolve: %s: not a valid champion blob: %s\n", duel_esc(path), nrt_strerror(err));
        duel_insp_free(x);
        return -1;
    }
    if (duel_netgraph_build(&x->g, n) != 0) {
        fprintf(stderr, "duel_evolve: %s: out of memory\n", duel_esc(path));
        duel_insp_free(x);
        return -1;
    }
    return 0;
}

static uint32_t duel_insp_rd32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

/* ---- inspect ------------------------------------------------------------ */

/* Whether the file at path starts with these 8 bytes (what kind of file inspect was given). */
static int duel_starts_with(const char *path, const char magic[8])
{
    char head[8];
    FILE *f = duel_fopen_regular(path);
    int yes;
    if (f == NULL)
        return 0;
    yes = fread(head, 1, 8, f) == 8 && memcmp(head, magic, 8) == 0;
    fclose(f);
    return yes;
}

/* A run directory, or a file that starts like a checkpoint (a coevolution's, or a population's: a run against
 * fixed opponents). */
static int duel_is_checkpoint(const char *path)
{
    struct stat st;
    uint8_t head[8];
    FILE *f;
    int kind = NEAT_CKPT_NONE;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
        return 1;
    if ((f = duel_fopen_regular(path)) == NULL)
        return 0;
    if (fread(head, 1, 8, f) == 8)
        kind = neat_checkpoint_kind(head, 8);
    fclose(f);
    return kind != NEAT_CKPT_NONE;
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
    if (duel_starts_with(argv[0], NEAT_GENOME_FILE_MAGIC) && duel_inspect_genome(argv[0]) != 0)
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
    printf("recurrent: %u (on a directed cycle, self-loops included)\n", x.g.n_recurrent);
    printf("ram: %lu bytes (nrt_mem_required)\n", (unsigned long)x.mem_required);
    printf("names: %s\n", x.g.duel_names ? "duel sensors and motors" : "generic (not the duel's 13 inputs and 3 outputs)");
    printf("nodes (index, kind, name, connections in and out):\n");
    for (v = 0; v < n->n_nodes; v++) {
        char buf[DUEL_NETGRAPH_NAME];
        printf("node %3u  %-6s  %-16s  in %3lu  out %3lu\n", v, duel_netgraph_kind(&x.g, v), duel_netgraph_name(&x.g, v, buf),
               (unsigned long)x.g.n_in[v], (unsigned long)x.g.n_out[v]);
    }
    printf("connections (index, source -> target, weight, raw Q3.12):\n");
    for (k = 0; k < n->n_conns; k++) {
        char b1[DUEL_NETGRAPH_NAME], b2[DUEL_NETGRAPH_NAME];
        printf("conn %4lu  %-16s -> %-16s  weight %7.4f  raw %6d%s\n", (unsigned long)k,
               duel_netgraph_name(&x.g, n->src[k], b1), duel_netgraph_name(&x.g, x.g.dst[k], b2),
               n->weight[k] / 4096.0, (int)n->weight[k], x.g.recurrent[k] ? "  recurrent" : "");
    }
    duel_insp_free(&x);
    return rc;
}

/* ---- dot ------------------------------------------------------------------ */

/* s as text inside a Graphviz HTML-like label: &, <, >, " as entities,
 * control characters replaced. */
static void duel_dot_html(FILE *f, const char *s)
{
    for (; *s != '\0'; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '&')
            fputs("&amp;", f);
        else if (c == '<')
            fputs("&lt;", f);
        else if (c == '>')
            fputs("&gt;", f);
        else if (c == '"')
            fputs("&quot;", f);
        else
            fputc(c < 0x20 || c == 0x7f ? '?' : c, f);
    }
}

/* Pen-width samples for the legend: bars 22 points long, h[i] high, in colour. */
static void duel_dot_bars(FILE *f, const char *colour, const double *h, int n)
{
    int i;
    fprintf(f, "<TD ALIGN=\"RIGHT\"><TABLE BORDER=\"0\" CELLSPACING=\"3\" CELLPADDING=\"0\"><TR>");
    for (i = 0; i < n; i++)
        fprintf(f, "<TD BGCOLOR=\"%s\" WIDTH=\"22\" HEIGHT=\"%.0f\" FIXEDSIZE=\"TRUE\"></TD>", colour,
                h[i] < 1 ? 1 : h[i]);
    fprintf(f, "</TR></TABLE></TD>");
}

/* The pen width of a connection of weight raw (Q3.12): 0.5 to 3 points. */
static double duel_dot_pen(int raw)
{
    return 0.5 + 2.5 * (raw < 0 ? -raw : raw) / 4096.0 / 8.0;
}

/* Whether connection k is drawn: |w| >= min_weight (exact: raw / 4096 is a
 * double without rounding). */
static int duel_dot_shown(const duel_insp *x, uint32_t k, const duel_dot_opts *o)
{
    int raw = x->net.weight[k];
    return (raw < 0 ? -raw : raw) / 4096.0 >= o->min_weight;
}

/* The title and the legend, as the graph's label at the bottom: what each
 * colour, width, line and node style means, in the picture itself (four
 * columns: sample, meaning, sample, meaning). */
static void duel_dot_legend(FILE *f, const duel_insp *x, const duel_dot_opts *o, uint32_t n_shown)
{
    const nrt_net *n = &x->net;
    const double two[1] = {2}, widths[3] = {duel_dot_pen(4096), duel_dot_pen(4 * 4096), duel_dot_pen(8 * 4096 - 1)};
    fprintf(f, "  graph [labelloc=b, labeljust=c, label=<<TABLE BORDER=\"0\" CELLSPACING=\"1\" CELLPADDING=\"1\">\n"
               "    <TR><TD COLSPAN=\"4\"><B>");
    duel_dot_html(f, x->path);
    fprintf(f, "</B>: %u inputs (bias included), %u outputs, %u hidden (%u dead), %u connections (%u recurrent)",
            (unsigned)n->n_inputs, (unsigned)n->n_outputs, (unsigned)n->n_hidden, x->g.n_dead, (unsigned)n->n_conns,
            x->g.n_recurrent);
    if (o->min_weight > 0)
        fprintf(f, "; %lu drawn, those of |w| &lt; %g left out", (unsigned long)n_shown, o->min_weight);
    fprintf(f, "</TD></TR>\n    <TR>");
    duel_dot_bars(f, "black", two, 1);
    fprintf(f, "<TD ALIGN=\"LEFT\">positive weight</TD><TD ALIGN=\"RIGHT\">boxes:</TD>"
               "<TD ALIGN=\"LEFT\">sensor inputs at the bottom (<FONT COLOR=\"gray55\">grey: unused</FONT>), motor "
               "outputs at the top</TD></TR>\n    <TR>");
    duel_dot_bars(f, "red", two, 1);
    fprintf(f, "<TD ALIGN=\"LEFT\">negative weight</TD><TD ALIGN=\"RIGHT\">circles:</TD>"
               "<TD ALIGN=\"LEFT\">hidden nodes in rows by depth (longest feed-forward path from an input), deeper "
               "higher</TD></TR>\n    <TR>");
    duel_dot_bars(f, "black", widths, 3);
    fprintf(f, "<TD ALIGN=\"LEFT\">|w| = 1, 4, 8 (width 0.5 + 2.5 |w| / 8)</TD>"
               "<TD ALIGN=\"RIGHT\"><FONT COLOR=\"gray55\">grey dashed:</FONT></TD>"
               "<TD ALIGN=\"LEFT\">dead hidden node: no input reaches it, or it reaches no output</TD></TR>\n"
               "    <TR><TD ALIGN=\"RIGHT\">- - - -</TD><TD ALIGN=\"LEFT\">recurrent (on a cycle)</TD>"
               "<TD ALIGN=\"RIGHT\"><FONT COLOR=\"gray55\">grey lines:</FONT></TD>"
               "<TD ALIGN=\"LEFT\">connections of a dead node</TD></TR>\n  </TABLE>>];\n");
}

static void duel_dot_write(FILE *f, const duel_insp *x, const duel_dot_opts *o)
{
    const nrt_net *n = &x->net;
    unsigned v, n_io = (unsigned)(n->n_inputs + n->n_outputs);
    uint32_t k, n_shown = 0;
    int d;
    char buf[DUEL_NETGRAPH_NAME];

    for (k = 0; k < n->n_conns; k++)
        n_shown += (uint32_t)duel_dot_shown(x, k, o);
    fprintf(f, "/* duel_evolve dot: a champion network (docs/tools.md) */\ndigraph champion {\n");
    /* at most 20 x 14 inches at 96 dpi (1920 x 1344 pixels): a large network is scaled down, not a poster */
    fprintf(f, "  rankdir=BT;\n  nodesep=0.08;\n  ranksep=0.8;\n  dpi=96;\n  size=\"20,14\";\n");
    /* boxes just round their names: 13 sensors side by side are the width of the picture */
    fprintf(f, "  node [fontname=\"Helvetica\", fontsize=11, margin=\"0.04,0.02\", height=0.3];\n  edge [arrowsize=0.6];\n");
    fprintf(f, "  graph [fontname=\"Helvetica\", fontsize=12];\n");
    duel_dot_legend(f, x, o, n_shown);

    /* inputs in one rank at the bottom, in sensor order (invisible flat edges) */
    fprintf(f, "  subgraph inputs {\n    rank=source;\n");
    for (v = 0; v < n->n_inputs; v++)
        fprintf(f, "    n%u [label=\"%s\", shape=box%s];\n", v, duel_netgraph_name(&x->g, v, buf),
                x->g.n_out[v] == 0 ? ", color=gray70, fontcolor=gray55" : "");
    if (n->n_inputs > 1) {
        fprintf(f, "    ");
        for (v = 0; v < n->n_inputs; v++)
            fprintf(f, "n%u%s", v, v + 1 < n->n_inputs ? " -> " : " [style=invis];\n");
    }
    fprintf(f, "  }\n");

    /* outputs in one rank at the top */
    fprintf(f, "  subgraph outputs {\n    rank=sink;\n");
    for (v = n->n_inputs; v < n_io; v++)
        fprintf(f, "    n%u [label=\"%s\", shape=box, style=bold];\n", v, duel_netgraph_name(&x->g, v, buf));
    if (n->n_outputs > 1) {
        fprintf(f, "    ");
        for (v = n->n_inputs; v < n_io; v++)
            fprintf(f, "n%u%s", v, v + 1 < n_io ? " -> " : " [style=invis];\n");
    }
    fprintf(f, "  }\n");

    /* hidden nodes, a rank per depth, the layers the legend names; a depth
     * of many nodes in rows of DUEL_DOT_ROW stacked by invisible edges (one
     * row of 20 makes a picture five times as wide as high) */
    for (d = 1; d <= x->g.max_depth; d++) {
        unsigned in_row = 0, row_first = 0;
        for (v = n_io; v < n->n_nodes; v++) {
            if (x->g.depth[v] != d)
                continue;
            if (in_row == DUEL_DOT_ROW) {
                fprintf(f, "  }\n  n%u -> n%u [style=invis];\n", row_first, v);
                in_row = 0;
            }
            if (in_row == 0) {
                fprintf(f, "  subgraph depth%d_%u {\n    rank=same;\n", d, v);
                row_first = v;
            }
            in_row++;
            fprintf(f, "    n%u [label=\"%s\", shape=circle, width=0.3, fixedsize=false%s];\n", v,
                    duel_netgraph_name(&x->g, v, buf), x->g.dead[v] ? ", style=dashed, color=gray60, fontcolor=gray55" : "");
        }
        if (in_row > 0)
            fprintf(f, "  }\n");
    }

    /* one edge per connection drawn; only the feed-forward ones (a DAG) set the ranks */
    for (k = 0; k < n->n_conns; k++) {
        int w = n->weight[k];
        unsigned s = n->src[k], t = x->g.dst[k];
        const char *colour = w < 0 ? "red" : "black";
        if (!duel_dot_shown(x, k, o))
            continue;
        if (x->g.dead[s] || x->g.dead[t]) /* its signal never gets from a sensor to a motor */
            colour = w < 0 ? "\"#f0a0a0\"" : "gray60";
        fprintf(f, "  n%u -> n%u [penwidth=%.2f, color=%s, tooltip=\"%.4f\"%s%s];\n", s, t, duel_dot_pen(w), colour,
                w / 4096.0, x->g.recurrent[k] ? ", style=dashed" : "",
                duel_netgraph_layering(&x->g, k) ? "" : ", constraint=false");
    }
    fprintf(f, "}\n");
}

int duel_dot_parse_min_weight(const char *cmd, const char *v, duel_dot_opts *o)
{
    char *end;
    double w;
    errno = 0;
    w = strtod(v, &end);
    if (*v == '\0' || *end != '\0' || errno || !(w >= 0 && w <= 8)) { /* !(..) also refuses NaN */
        fprintf(stderr, "duel_evolve: %s: --min-weight takes a number from 0 to 8, not '%s'\n", cmd, duel_esc(v));
        return -1;
    }
    o->min_weight = w;
    return 0;
}

int duel_dot_blob(FILE *f, const char *path, const duel_dot_opts *o)
{
    duel_insp x;
    if (duel_insp_open(&x, path) != 0)
        return -1;
    duel_dot_write(f, &x, o);
    duel_insp_free(&x);
    return 0;
}

/* duel_file_write_with's context and callback */
typedef struct duel_dot_job {
    const duel_insp *x;
    const duel_dot_opts *o;
} duel_dot_job;

static void duel_dot_write_cb(FILE *f, const void *ctx)
{
    const duel_dot_job *j = (const duel_dot_job *)ctx;
    duel_dot_write(f, j->x, j->o);
}

int duel_cmd_dot(int argc, char **argv)
{
    duel_insp x;
    duel_dot_opts o = {0};
    duel_dot_job job;
    const char *blob = NULL, *out = NULL;
    int i, rc = 0, force = 0;

    for (i = 0; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "duel_evolve: dot: -o needs a file name\n");
                return 2;
            }
            out = argv[++i];
        } else if (strcmp(argv[i], "--force") == 0) {
            force = 1;
        } else if (strcmp(argv[i], "--min-weight") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "duel_evolve: dot: --min-weight needs a value\n");
                return 2;
            }
            if (duel_dot_parse_min_weight("dot", argv[++i], &o) != 0)
                return 2;
        } else if (argv[i][0] == '-' || blob != NULL) {
            fprintf(stderr, "usage: duel_evolve dot BLOB [-o FILE.dot [--force]] [--min-weight W]\n");
            return 2;
        } else {
            blob = argv[i];
        }
    }
    if (blob == NULL) {
        fprintf(stderr, "usage: duel_evolve dot BLOB [-o FILE.dot [--force]] [--min-weight W]\n");
        return 2;
    }
    if (out != NULL) {
        static const duel_out_kind kind = {"a Graphviz file from duel_evolve dot", "/* duel_evolve dot:", NULL};
        if (duel_out_allowed("dot", "-o", out, &kind, force, &blob, 1) != 0)
            return 2;
    }
    if (duel_insp_open(&x, blob) != 0)
        return 2;
    job.x = &x;
    job.o = &o;
    if (out != NULL) {
        rc = duel_file_write_with(out, duel_dot_write_cb, &job);
    } else {
        duel_dot_write(stdout, &x, &o); /* a failing stdout: duel_evolve.c says so */
    }
    duel_insp_free(&x);
    return rc;
}
