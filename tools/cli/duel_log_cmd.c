/* duel_log_cmd.c - `duel_evolve log info|dump`: a duel recorded as an LCM event log, summarised or printed as CSV, with no Java tool. */
#include <stdlib.h>
#include <string.h>

#include "duel_cli.h"
#include "duel_lcm.h"
#include "duel_text.h"
#include "duel_world_cfg.h"
#include "duel_trace.h"

static void duel_log_usage(void)
{
    fprintf(stderr, "usage: duel_evolve log info FILE.lcm\n"
                    "       duel_evolve log dump FILE.lcm [--channel C]\n"
                    "  C: DUEL_STATE, DUEL_SENSE_WEST, DUEL_SENSE_EAST, DUEL_MOTOR_WEST, DUEL_MOTOR_EAST or DUEL_NET (docs/lcm.md)\n");
}

static int duel_log_cmp_channel(const void *a, const void *b)
{
    return strcmp(((const duel_lcm_channel *)a)->name, ((const duel_lcm_channel *)b)->name);
}

static int duel_log_info(const char *path)
{
    duel_lcm_game *g;
    char err[4600];
    size_t i;
    int status = duel_lcm_game_read(&g, path, err, sizeof err);

    if (g == NULL) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    if (g->n_channels > 1) /* qsort of NULL, even of nothing, is undefined */
        qsort(g->channels, g->n_channels, sizeof *g->channels, duel_log_cmp_channel);
    printf("file: %s\n", path);
    printf("size: %llu bytes, %llu events%s\n", (unsigned long long)g->size, (unsigned long long)g->events,
           g->truncated ? " before a truncated or corrupt one" : "");
    /* as doubles: a crafted log's timestamps may be any int64, whose difference overflows */
    printf("duration: %.6f s (first to last event)\n", ((double)g->last_utime - (double)g->first_utime) / 1e6);
    for (i = 0; i < g->n_channels; i++)
        printf("channel %s: %llu messages\n", g->channels[i].name, (unsigned long long)g->channels[i].count);
    if (g->started) {
        char esc_w[1100], esc_e[1100];
        if (g->food_config < 0)
            printf("game: training food, west %s, east %s\n", duel_text_escape(g->name[0], esc_w, sizeof esc_w),
                   duel_text_escape(g->name[1], esc_e, sizeof esc_e));
        else
            printf("game: food configuration %d, west %s, east %s\n", g->food_config,
                   duel_text_escape(g->name[0], esc_w, sizeof esc_w), duel_text_escape(g->name[1], esc_e, sizeof esc_e));
        if (g->have_world) {
            char label[40];
            printf("world: %s (its rules in the log's world message)\n",
                   duel_world_label(&g->rules, label, sizeof label));
        }
        if (g->step[0] != DUEL_TRACE_STEP_UNKNOWN || g->step[1] != DUEL_TRACE_STEP_UNKNOWN)
            printf("network step: west %s, east %s\n", duel_trace_step_name(g->step[0]),
                   duel_trace_step_name(g->step[1]));
        else
            printf("network step: not recorded (a log without net messages)\n");
        printf("complete steps: %lu\n", (unsigned long)g->rows);
        if (g->hellos != 0)
            printf("controller hellos: %llu\n", (unsigned long long)g->hellos);
        if (g->after_end != 0)
            printf("events after the end of the game: %llu (not read)\n", (unsigned long long)g->after_end);
    }
    if (g->over) {
        const duel_world *w = &g->final_w;
        printf("outcome: %s after %lu steps\n", duel_lcm_outcome_text(w->outcome, g->forfeit),
               (unsigned long)g->final_step);
        printf("energy: west %.6f, east %.6f; food eaten: west %u, east %u\n", w->robot[0].energy / 65536.0,
               w->robot[1].energy / 65536.0, (unsigned)w->robot[0].eaten, (unsigned)w->robot[1].eaten);
    } else {
        printf("outcome: none recorded\n");
    }
    duel_lcm_game_free(g);
    if (status != 0) {
        fflush(stdout);
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    return 0;
}

/* The game as `play --trace` prints it. */
static int duel_log_dump_trace(const char *path)
{
    duel_lcm_game *g;
    duel_trace tr;
    char err[4600];
    uint32_t t;
    int status = duel_lcm_game_read(&g, path, err, sizeof err);

    if (status == -1) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        duel_lcm_game_free(g);
        return 2;
    }
    tr.f = stdout;
    tr.world_id = duel_rules_id(&g->rules);
    tr.step[0] = g->step[0];
    tr.step[1] = g->step[1];
    duel_trace_header(stdout);
    for (t = 0; t < g->rows; t++)
        duel_trace_row(&tr, &g->w[t], (const nrt_q15(*)[DUEL_N_INPUTS])g->in[t],
                       (const nrt_q15(*)[DUEL_N_OUTPUTS])g->out[t], &g->ev[t + 1]);
    duel_lcm_game_free(g);
    if (fflush(stdout) != 0 || ferror(stdout))
        return 1; /* duel_evolve.c says so */
    if (status != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    return 0;
}

/* A CSV field: quoted when it holds a comma, a quote or a line break. */
static void duel_log_csv_string(const char *s)
{
    if (strpbrk(s, ",\"\r\n") == NULL) {
        fputs(s, stdout);
        return;
    }
    putchar('"');
    for (; *s; s++) {
        if (*s == '"')
            putchar('"');
        putchar(*s);
    }
    putchar('"');
}

static void duel_log_state_header(void)
{
    static const char *const side[2] = {"west", "east"};
    int s, i;
    printf("step,food_config,west_controller,east_controller");
    for (s = 0; s < 2; s++)
        printf(",%s_x,%s_y,%s_heading,%s_energy,%s_eaten,%s_eaten_by", side[s], side[s], side[s], side[s], side[s],
               side[s]);
    printf(",n_food,food_mask,outcome,forfeit");
    for (i = 0; i < DUEL_MAX_FOOD; i++)
        printf(",food%d_x,food%d_y", i, i);
    printf("\n");
}

static void duel_log_state_row(const duel_state_t *m)
{
    int s, i;
    printf("%ld,%ld,", (long)m->step, (long)m->food_config);
    duel_log_csv_string(m->controller[0]);
    putchar(',');
    duel_log_csv_string(m->controller[1]);
    for (s = 0; s < 2; s++)
        printf(",%ld,%ld,%ld,%ld,%d,%ld", (long)m->x[s], (long)m->y[s], (long)m->heading[s], (long)m->energy[s],
               m->eaten[s], (long)m->eaten_by[s]);
    printf(",%d,%ld,%d,%d", m->n_food, (long)m->food_mask, m->outcome, m->forfeit);
    for (i = 0; i < DUEL_MAX_FOOD; i++)
        printf(",%ld,%ld", (long)m->food_x[i], (long)m->food_y[i]);
    printf("\n");
}

/* One channel's messages, every field as its raw integer. */
static int duel_log_dump_channel(const char *path, const char *channel)
{
    duel_lcm_reader rd;
    duel_lcm_event e;
    char err[4600], msg[400];
    int kind, rc = 0, i, bad = 0;
    uint64_t n = 0;

    if (strcmp(channel, DUEL_CH_STATE) == 0)
        kind = 0;
    else if (strcmp(channel, DUEL_CH_SENSE_WEST) == 0 || strcmp(channel, DUEL_CH_SENSE_EAST) == 0)
        kind = 1;
    else if (strcmp(channel, DUEL_CH_MOTOR_WEST) == 0 || strcmp(channel, DUEL_CH_MOTOR_EAST) == 0)
        kind = 2;
    else if (strcmp(channel, DUEL_CH_NET) == 0)
        kind = 3;
    else {
        fprintf(stderr, "duel_evolve: log dump: unknown channel '%s' (DUEL_STATE, DUEL_SENSE_WEST, DUEL_SENSE_EAST, "
                        "DUEL_MOTOR_WEST, DUEL_MOTOR_EAST, DUEL_NET)\n", duel_esc(channel));
        return 2;
    }
    if (duel_lcm_reader_open(&rd, path, err, sizeof err) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    while (!bad && (rc = duel_lcm_reader_next(&rd, &e, err, sizeof err)) == 1) {
        if (strcmp(e.channel, channel) != 0)
            continue;
        if (n++ == 0) {
            if (kind == 0)
                duel_log_state_header();
            else if (kind == 1)
                printf("step,side,input0,input1,input2,input3,input4,input5,input6,input7,input8,input9,input10,"
                       "input11,input12\n");
            else if (kind == 2)
                printf("step,side,output0,output1,output2,controller\n");
            else
                printf("side,step,controller\n");
        }
        if (kind == 0) {
            duel_state_t m;
            bad = duel_msg_decode_state(e.data, e.len, &m, msg, sizeof msg);
            if (!bad) {
                duel_log_state_row(&m);
                duel_state_t_decode_cleanup(&m);
            }
        } else if (kind == 1) {
            duel_sense_t m;
            bad = duel_msg_decode_sense(e.data, e.len, &m, msg, sizeof msg);
            if (!bad) {
                printf("%ld,%d", (long)m.step, m.side);
                for (i = 0; i < DUEL_N_INPUTS; i++)
                    printf(",%d", m.input[i]);
                printf("\n");
            }
        } else if (kind == 3) {
            duel_net_t m;
            bad = duel_msg_decode_net(e.data, e.len, &m, msg, sizeof msg);
            if (!bad) {
                printf("%d,%d,", m.side, m.step);
                duel_log_csv_string(m.controller);
                printf("\n");
                duel_net_t_decode_cleanup(&m);
            }
        } else {
            duel_motor_t m;
            bad = duel_msg_decode_motor(e.data, e.len, &m, msg, sizeof msg);
            if (!bad) {
                printf("%ld,%d,%d,%d,%d,", (long)m.step, m.side, m.output[0], m.output[1], m.output[2]);
                duel_log_csv_string(m.controller);
                printf("\n");
                duel_motor_t_decode_cleanup(&m);
            }
        }
        if (bad)
            snprintf(err, sizeof err, "%s: event %llu at offset %llu: %s: %s", path, (unsigned long long)e.index,
                     (unsigned long long)e.offset, channel, msg);
    }
    duel_lcm_reader_close(&rd);
    if (fflush(stdout) != 0 || ferror(stdout))
        return 1; /* duel_evolve.c says so */
    if (bad || rc < 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err));
        return 2;
    }
    if (n == 0) {
        fprintf(stderr, "duel_evolve: %s: no messages on channel %s\n", duel_esc(path), channel);
        return 2;
    }
    return 0;
}

int duel_cmd_log(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[0], "info") == 0)
        return duel_log_info(argv[1]);
    if (argc == 2 && strcmp(argv[0], "dump") == 0)
        return duel_log_dump_trace(argv[1]);
    if (argc == 4 && strcmp(argv[0], "dump") == 0 && strcmp(argv[2], "--channel") == 0)
        return duel_log_dump_channel(argv[1], argv[3]);
    if (argc >= 1 && strcmp(argv[0], "info") != 0 && strcmp(argv[0], "dump") != 0) {
        fprintf(stderr, "duel_evolve: unknown log command '%s' (info, dump)\n", duel_esc(argv[0]));
        return 2;
    }
    if (argc >= 3 && strcmp(argv[0], "dump") == 0 && strcmp(argv[2], "--channel") != 0) {
        fprintf(stderr, "duel_evolve: log dump: unknown option '%s' (--channel C)\n", duel_esc(argv[2]));
        return 2;
    }
    duel_log_usage();
    return 2;
}
