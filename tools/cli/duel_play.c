/* duel_play.c - `duel_evolve play A B`: one game, or the 288-game comparison, between two controllers, as text or JSON. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "duel_cli.h"
#include "duel_text.h"
#include "duel_ctrl.h"
#include "duel_files.h"
#include "duel_json.h"
#include "duel_lcm.h"
#include "duel_outputs.h"
#include "duel_trace.h"
#include "duel_world_cfg.h"

static void duel_play_usage(void)
{
    fprintf(stderr, "usage: duel_evolve play A B [--games 288 | --food K|training --side west|east] [--trace FILE.csv] "
                    "[--lcm-log FILE.lcm] [--force] [--world NAME|FILE] [--json]\n"
                    "  A, B: a champion blob or genome file, or builtin:NAME (idle, spinner, forager, hunter, "
                    "forager-hunter); the world: --world's, else the runs' the champions come from, else v1\n");
}

/* The outcome as a JSON word (docs/tools.md, "play --json"). */
static const char *duel_outcome_key(int outcome)
{
    switch (outcome) {
    case DUEL_WEST_WINS: return "west_wins";
    case DUEL_EAST_WINS: return "east_wins";
    case DUEL_DRAW: return "draw";
    default: return "timeout";
    }
}

/* What the game was played in: its world, where that came from, and each side's step. */
typedef struct duel_play_ctx {
    const duel_rules *world;
    const char *world_from; /* "--world", "champions" or "default" */
} duel_play_ctx;

/* The world and the step modes as the end of a JSON object: ,"world":...} */
static void duel_play_json_world(const duel_play_ctx *x, const char *ka, const duel_cli_ctrl *a, const char *kb,
                                 const duel_cli_ctrl *b)
{
    char label[40];
    printf(",\"world\":");
    duel_json_str(stdout, duel_world_label(x->world, label, sizeof label));
    printf(",\"world_id\":\"%016llx\",\"world_from\":\"%s\",\"step\":{\"%s\":\"%s\",\"%s\":\"%s\"}}\n",
           (unsigned long long)duel_rules_id(x->world), x->world_from, ka, duel_origin_step_text(&a->origin), kb,
           duel_origin_step_text(&b->origin));
}

/* The same as a line of text (where the world came from: --json's world_from, and a note on stderr when it is
 * the default for lack of a recorded one). */
static void duel_play_text_world(const duel_play_ctx *x, const duel_cli_ctrl *a, const duel_cli_ctrl *b)
{
    const char *name = duel_rules_name(x->world);
    printf("world %s (identity %016llx); network step: A %s, B %s\n", name != NULL ? name : "custom",
           (unsigned long long)duel_rules_id(x->world), duel_origin_step_text(&a->origin),
           duel_origin_step_text(&b->origin));
}

/* One game as one JSON object on stdout. */
static void duel_play_json_game(const duel_play_ctx *x, const duel_cli_ctrl *w, const duel_cli_ctrl *e, int food,
                                const duel_result *r)
{
    const char *west = w->name, *east = e->name;
    printf("{\"games\":1,\"food\":");
    if (food < 0)
        printf("\"training\"");
    else
        printf("%d", food);
    printf(",\"west\":");
    duel_json_str(stdout, west);
    printf(",\"east\":");
    duel_json_str(stdout, east);
    printf(",\"outcome\":\"%s\",\"steps\":%u,\"energy\":[%.6f,%.6f],\"eaten\":[%u,%u]",
           duel_outcome_key(r->outcome), (unsigned)r->steps, r->energy[0] / 65536.0, r->energy[1] / 65536.0,
           (unsigned)r->eaten[0], (unsigned)r->eaten[1]);
    duel_play_json_world(x, "west", w, "east", e);
}

/* A 288-game comparison as one JSON object on stdout. */
static void duel_play_json_tally(const duel_play_ctx *x, const duel_cli_ctrl *ca, const duel_cli_ctrl *cb,
                                 const duel_tally *t)
{
    const char *a = ca->name, *b = cb->name;
    printf("{\"games\":%u,\"a\":", 2u * DUEL_CONFIGS);
    duel_json_str(stdout, a);
    printf(",\"b\":");
    duel_json_str(stdout, b);
    printf(",\"a_wins\":%u,\"b_wins\":%u,\"draws\":%u,\"timeouts\":%u,\"superior\":%s", t->wins_a,
           t->wins_b, t->draws, t->timeouts,
           t->wins_a > t->wins_b ? "\"a\"" : (t->wins_b > t->wins_a ? "\"b\"" : "null"));
    duel_play_json_world(x, "a", ca, "b", cb);
}

/* A champion played in another world than its own (--world asks for it), or in the default world because it
 * records none (a blob never does), is said so, once, on stderr. */
static void duel_play_note_world(const duel_cli_ctrl *c, const char *which, const duel_rules *world)
{
    char a[40], b[40];
    if (c->origin.world_from != DUEL_ORIGIN_NONE && !duel_rules_equal(&c->origin.world, world))
        fprintf(stderr, "duel_evolve: play: note: %s (%s) was made in world %s; played in world %s as --world asks\n",
                which, duel_esc(c->name), duel_world_label(&c->origin.world, a, sizeof a), duel_world_label(world, b, sizeof b));
}

static void duel_play_note_default(const duel_cli_ctrl *c, const char *which)
{
    if (!c->origin.builtin && c->origin.world_from == DUEL_ORIGIN_NONE)
        fprintf(stderr, "duel_evolve: play: note: %s (%s) records no world (%s): played in world v1, the default "
                        "(--world chooses another)\n", which, duel_esc(c->name),
                c->origin.genome ? "a genome file of format 1 outside any run" : "a blob never does; its run's "
                                                                                 "genome file does");
}

int duel_cmd_play(int argc, char **argv)
{
    duel_cli_ctrl a, b;
    const char *trace_path = NULL, *lcm_path = NULL, *world_arg = NULL;
    duel_rules world = *duel_rules_v1();
    duel_play_ctx x;
    int i, food = DUEL_TRAINING, a_west = 1, games = 1, rc = 0, err, json = 0, found = 0, force = 0;

    if (argc < 2) {
        duel_play_usage();
        return 2;
    }
    for (i = 2; i < argc; i++) {
        const char *opt = argv[i];
        if (strcmp(opt, "--json") == 0) {
            json = 1;
            continue;
        }
        if (strcmp(opt, "--force") == 0) {
            force = 1;
            continue;
        }
        if (i + 1 >= argc) {
            static const char *const takes[] = {"--games", "--food", "--side", "--trace", "--lcm-log", "--world", NULL};
            return duel_cli_missing_value("play", opt, takes);
        }
        if (strcmp(opt, "--games") == 0) {
            if (strcmp(argv[++i], "288") != 0 && strcmp(argv[i], "1") != 0) {
                fprintf(stderr, "duel_evolve: play: --games takes 1 or 288, not '%s'\n", duel_esc(argv[i]));
                return 2;
            }
            games = atoi(argv[i]);
        } else if (strcmp(opt, "--food") == 0) {
            char *end;
            const char *v = argv[++i];
            long k;
            if (strcmp(v, "training") == 0) {
                food = DUEL_TRAINING;
                continue;
            }
            errno = 0;
            k = strtol(v, &end, 10);
            if (*v == '\0' || *end != '\0' || errno || k < 0 || k >= DUEL_CONFIGS) {
                fprintf(stderr, "duel_evolve: play: bad food configuration '%s' (0..143 or training)\n", duel_esc(v));
                return 2;
            }
            food = (int)k;
        } else if (strcmp(opt, "--side") == 0) {
            const char *v = argv[++i];
            if (strcmp(v, "west") != 0 && strcmp(v, "east") != 0) {
                fprintf(stderr, "duel_evolve: play: --side takes west or east, not '%s'\n", duel_esc(v));
                return 2;
            }
            a_west = strcmp(v, "west") == 0;
        } else if (strcmp(opt, "--trace") == 0) {
            trace_path = argv[++i];
        } else if (strcmp(opt, "--lcm-log") == 0) {
            lcm_path = argv[++i];
        } else if (strcmp(opt, "--world") == 0) {
            world_arg = argv[++i];
        } else {
            fprintf(stderr, "duel_evolve: play: unknown option '%s' (see duel_evolve --help)\n", duel_esc(opt));
            return 2;
        }
    }
    if (games == 288 && (trace_path != NULL || lcm_path != NULL)) {
        fprintf(stderr, "duel_evolve: play: %s records one game, not the 288 of a comparison\n",
                trace_path != NULL ? "--trace" : "--lcm-log");
        return 2;
    }
    {
        static const duel_out_kind trace_kind = {"a game trace", "t,west_x,west_y,", NULL};
        static const duel_out_kind log_kind = {"this project's LCM event log", NULL, duel_out_is_duel_lcm};
        const char *in[3];
        in[0] = argv[0];
        in[1] = argv[1];
        in[2] = lcm_path;
        if (trace_path != NULL && duel_out_allowed("play", "--trace", trace_path, &trace_kind, force, in, 3) != 0)
            return 2;
        in[2] = trace_path;
        if (lcm_path != NULL && duel_out_allowed("play", "--lcm-log", lcm_path, &log_kind, force, in, 3) != 0)
            return 2;
    }
    if (world_arg != NULL ? duel_world_arg(&world, world_arg) != 0
                          : duel_ctrl_world((const char *const *)argv, 2, &world, &found) != 0)
        return 2;
    if (duel_cli_ctrl_open(&a, argv[0]) != 0)
        return 2;
    if (duel_cli_ctrl_open(&b, argv[1]) != 0) {
        duel_cli_ctrl_close(&a);
        return 2;
    }
    x.world = &world;
    x.world_from = world_arg != NULL ? "--world" : found ? "champions" : "default";
    if (world_arg != NULL) {
        duel_play_note_world(&a, "A", &world);
        duel_play_note_world(&b, "B", &world);
    } else if (!found) {
        duel_play_note_default(&a, "A");
        duel_play_note_default(&b, "B");
    }
    if (games == 288) {
        duel_tally t;
        err = duel_compare_rules(&world, &a.ctrl, &b.ctrl, &t);
        if (err) {
            fprintf(stderr, "duel_evolve: play: comparison failed (%d)\n", err);
            rc = 1;
        } else if (json) {
            duel_play_json_tally(&x, &a, &b, &t);
        } else {
            printf("288 games (144 food configurations x 2 sides): A %s wins %u, B %s wins %u, draws %u, timeouts %u\n",
                   a.name, t.wins_a, b.name, t.wins_b, t.draws, t.timeouts);
            printf("%s\n", t.wins_a > t.wins_b ? "A is superior" : (t.wins_b > t.wins_a ? "B is superior" : "neither is superior"));
            duel_play_text_world(&x, &a, &b);
        }
    } else {
        duel_result r;
        duel_lcm_game_rec lg;
        duel_out trace;
        duel_trace tr;
        FILE *tf = NULL;
        if (trace_path != NULL) {
            /* written as TRACE.tmp, put in place only when the game and its log are */
            if (duel_out_open(&trace, trace_path) != 0) {
                fprintf(stderr, "duel_evolve: %s: cannot write: %s\n", duel_esc(trace_path), strerror(errno));
                duel_cli_ctrl_close(&a);
                duel_cli_ctrl_close(&b);
                return 2;
            }
            tf = trace.f;
            /* every row names the world and how each side stepped */
            tr.f = tf;
            tr.world_id = duel_rules_id(&world);
            tr.step[0] = duel_trace_step_of(a_west ? &a.ctrl : &b.ctrl);
            tr.step[1] = duel_trace_step_of(a_west ? &b.ctrl : &a.ctrl);
            duel_trace_header(tf);
        }
        if (lcm_path != NULL) {
            /* the LCM log records the game; the trace rows pass through it */
            char lerr[4400];
            if (duel_lcm_game_rec_open(&lg, lcm_path, food, a_west ? a.name : b.name, a_west ? b.name : a.name, lerr,
                                       sizeof lerr) != 0) {
                fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(lerr));
                if (tf != NULL)
                    duel_out_abort(&trace);
                duel_cli_ctrl_close(&a);
                duel_cli_ctrl_close(&b);
                return 2;
            }
            lg.next = tf ? duel_trace_row : NULL;
            lg.next_ud = &tr;
            duel_lcm_game_rec_world(&lg, &world);
            duel_lcm_game_rec_nets(&lg, a_west ? &a.ctrl : &b.ctrl, a_west ? &b.ctrl : &a.ctrl);
            err = a_west ? duel_play_rules(&world, &a.ctrl, &b.ctrl, food, &r, duel_lcm_game_rec_step, &lg)
                         : duel_play_rules(&world, &b.ctrl, &a.ctrl, food, &r, duel_lcm_game_rec_step, &lg);
            if (duel_lcm_game_rec_close(&lg, err == 0, lerr, sizeof lerr) != 0 && err == 0) {
                fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(lerr));
                rc = 1;
            }
        } else {
            err = a_west ? duel_play_rules(&world, &a.ctrl, &b.ctrl, food, &r, tf ? duel_trace_row : NULL, &tr)
                         : duel_play_rules(&world, &b.ctrl, &a.ctrl, food, &r, tf ? duel_trace_row : NULL, &tr);
        }
        if (tf != NULL) {
            if (err != 0 || rc != 0) {
                duel_out_abort(&trace);
            } else if (duel_out_commit(&trace) != 0) {
                fprintf(stderr, "duel_evolve: %s: write failed: %s\n", duel_esc(trace_path), strerror(errno));
                rc = 1;
            }
        }
        if (err) {
            fprintf(stderr, "duel_evolve: play: game failed (%d)\n", err);
            rc = 1;
        } else if (json) {
            duel_play_json_game(&x, a_west ? &a : &b, a_west ? &b : &a, food, &r);
        } else {
            const char *wname = a_west ? a.name : b.name, *ename = a_west ? b.name : a.name;
            if (food < 0)
                printf("training food, west %s, east %s\n", wname, ename);
            else
                printf("food configuration %d, west %s, east %s\n", food, wname, ename);
            printf("%s after %u steps\n", duel_outcome_text(r.outcome), (unsigned)r.steps);
            printf("energy: west %.6f, east %.6f; food eaten: west %u, east %u\n", r.energy[0] / 65536.0,
                   r.energy[1] / 65536.0, (unsigned)r.eaten[0], (unsigned)r.eaten[1]);
            duel_play_text_world(&x, &a, &b);
        }
    }
    duel_cli_ctrl_close(&a);
    duel_cli_ctrl_close(&b);
    return rc;
}
