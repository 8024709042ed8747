/* duel_node_cmd.c - `duel_evolve node controller|world`: the duel's LCM nodes from the command line. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "duel_cli.h"
#include "duel_outputs.h"
#include "duel_text.h"
#include "duel_ctrl.h"
#include "duel_lcm.h"
#include "duel_world_cfg.h"

static void duel_node_usage(void)
{
    fprintf(stderr, "usage: duel_evolve node controller BLOB --side west|east --lcm URL [--wait-ms N] [--timeout-ms N]\n"
                    "       duel_evolve node world --food K|training --lcm URL [--timeout-ms N] [--wait-ms N] "
                    "[--period-ms N] [--lcm-log FILE.lcm [--force]] [--world NAME|FILE]\n"
                    "  URL: an LCM provider, e.g. tcpq://127.0.0.1:7700 (docs/lcm.md)\n");
}

static int duel_node_ms(const char *opt, const char *v, int lo, int *out)
{
    char *end;
    long x;
    errno = 0;
    x = strtol(v, &end, 10);
    if (*v == '\0' || *end != '\0' || errno != 0 || x < lo || x > 3600000) {
        fprintf(stderr, "duel_evolve: node: %s takes milliseconds in [%d, 3600000], not '%s'\n", opt, lo, duel_esc(v));
        return -1;
    }
    *out = (int)x;
    return 0;
}

/* The exit status of a node error: bad messages are bad input. */
static int duel_node_status(int err)
{
    return err == DUEL_NODE_E_FINGERPRINT || err == DUEL_NODE_E_VERSION || err == DUEL_NODE_E_MALFORMED ? 2 : 1;
}

static lcm_t *duel_node_lcm(const char *url)
{
    lcm_t *lcm;
    if (url == NULL) {
        fprintf(stderr, "duel_evolve: node: --lcm URL is required (e.g. tcpq://127.0.0.1:7700)\n");
        return NULL;
    }
    /* multicast leaves the machine whatever its ttl: this project talks over
     * loopback only (memq://, tcpq://127.0.0.1:PORT, file://) */
    if (strncmp(url, "udpm://", 7) == 0 || strchr(url, ':') == NULL) {
        fprintf(stderr, "duel_evolve: node: '%s': UDP multicast is not used here; give memq://, file:// or "
                        "tcpq://127.0.0.1:PORT\n", duel_esc(url));
        return NULL;
    }
    lcm = duel_node_lcm_create(url);
    if (lcm == NULL)
        fprintf(stderr, "duel_evolve: node: cannot start LCM on '%s' (a bad URL, or no hub listening there)\n", duel_esc(url));
    return lcm;
}

static int duel_node_controller_cmd(int argc, char **argv)
{
    const char *url = NULL;
    int i, side = -1, wait_ms = 30000, timeout_ms = 10000, err;
    duel_cli_ctrl c;
    duel_node_ctrl node;
    lcm_t *lcm;

    if (argc < 1 || argv[0][0] == '-') {
        duel_node_usage();
        return 2;
    }
    for (i = 1; i < argc; i++) {
        const char *opt = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (v == NULL) {
            static const char *const takes[] = {"--side", "--lcm", "--wait-ms", "--timeout-ms", NULL};
            return duel_cli_missing_value("node controller", opt, takes);
        }
        i++;
        if (strcmp(opt, "--side") == 0) {
            if (strcmp(v, "west") != 0 && strcmp(v, "east") != 0) {
                fprintf(stderr, "duel_evolve: node controller: --side takes west or east, not '%s'\n", duel_esc(v));
                return 2;
            }
            side = strcmp(v, "west") == 0 ? 0 : 1;
        } else if (strcmp(opt, "--lcm") == 0) {
            url = v;
        } else if (strcmp(opt, "--wait-ms") == 0) {
            if (duel_node_ms(opt, v, 1, &wait_ms))
                return 2;
        } else if (strcmp(opt, "--timeout-ms") == 0) {
            if (duel_node_ms(opt, v, 1, &timeout_ms))
                return 2;
        } else {
            fprintf(stderr, "duel_evolve: node controller: unknown option '%s' (see duel_evolve --help)\n", duel_esc(opt));
            return 2;
        }
    }
    if (side < 0) {
        fprintf(stderr, "duel_evolve: node controller: --side west|east is required\n");
        return 2;
    }
    if (strncmp(argv[0], "builtin:", 8) == 0) {
        fprintf(stderr, "duel_evolve: node controller: %s: a node runs a champion blob through the runtime, not a "
                        "builtin strategy\n", duel_esc(argv[0]));
        return 2;
    }
    if (duel_cli_ctrl_open(&c, argv[0]) != 0)
        return 2;
    lcm = duel_node_lcm(url);
    if (lcm == NULL) {
        duel_cli_ctrl_close(&c);
        return 2;
    }
    err = duel_node_ctrl_start(&node, lcm, &c.net, side, c.name);
    if (err == 0)
        err = duel_node_ctrl_run(&node, wait_ms, timeout_ms);
    if (node.ignored)
        fprintf(stderr, "duel_evolve: node controller %s: ignored %lu malformed message%s; the first: %s\n",
                side ? "east" : "west", (unsigned long)node.ignored, node.ignored == 1 ? "" : "s", node.ignored_msg);
    if (err) {
        fprintf(stderr, "duel_evolve: node controller %s: %s\n", side ? "east" : "west",
                node.msg[0] ? node.msg : "cannot subscribe");
    } else {
        printf("%s controller %s: %lu steps; %s\n", side ? "east" : "west", c.name, (unsigned long)node.steps,
               duel_lcm_outcome_text(node.outcome, node.forfeit));
    }
    duel_node_ctrl_stop(&node);
    lcm_destroy(lcm);
    duel_cli_ctrl_close(&c);
    return err ? duel_node_status(err) : 0;
}

static int duel_node_world_cmd(int argc, char **argv)
{
    const char *url = NULL, *log_path = NULL;
    duel_node_world_opts o;
    duel_node_world_result r;
    duel_rules world;
    duel_lcm_rec rec;
    char err_text[4400];
    lcm_t *lcm;
    int i, err, have_food = 0, force = 0;
    const char *world_file = NULL;
    char esc_w[1100], esc_e[1100];

    memset(&o, 0, sizeof o);
    o.food_config = DUEL_TRAINING;
    o.timeout_ms = 1000;
    o.wait_ms = 30000;
    for (i = 0; i < argc; i++) {
        const char *opt = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(opt, "--force") == 0) {
            force = 1;
            continue;
        }
        if (v == NULL) {
            static const char *const takes[] = {"--food", "--lcm", "--timeout-ms", "--wait-ms", "--period-ms",
                                                "--lcm-log", "--world", NULL};
            return duel_cli_missing_value("node world", opt, takes);
        }
        i++;
        if (strcmp(opt, "--food") == 0) {
            char *end;
            long k;
            have_food = 1;
            if (strcmp(v, "training") == 0)
                continue;
            errno = 0;
            k = strtol(v, &end, 10);
            if (*v == '\0' || *end != '\0' || errno || k < 0 || k >= DUEL_CONFIGS) {
                fprintf(stderr, "duel_evolve: node world: bad food configuration '%s' (0..143 or training)\n", duel_esc(v));
                return 2;
            }
            o.food_config = (int)k;
        } else if (strcmp(opt, "--lcm") == 0) {
            url = v;
        } else if (strcmp(opt, "--timeout-ms") == 0) {
            if (duel_node_ms(opt, v, 1, &o.timeout_ms))
                return 2;
        } else if (strcmp(opt, "--wait-ms") == 0) {
            if (duel_node_ms(opt, v, 1, &o.wait_ms))
                return 2;
        } else if (strcmp(opt, "--period-ms") == 0) {
            if (duel_node_ms(opt, v, 0, &o.period_ms))
                return 2;
        } else if (strcmp(opt, "--world") == 0) {
            if (duel_world_arg(&world, v) != 0)
                return 2;
            o.rules = &world;
            world_file = v;
        } else if (strcmp(opt, "--lcm-log") == 0) {
            log_path = v;
        } else {
            fprintf(stderr, "duel_evolve: node world: unknown option '%s' (see duel_evolve --help)\n", duel_esc(opt));
            return 2;
        }
    }
    if (!have_food) {
        fprintf(stderr, "duel_evolve: node world: --food K|training is required\n");
        return 2;
    }
    if (log_path != NULL) {
        static const duel_out_kind log_kind = {"this project's LCM event log", NULL, duel_out_is_duel_lcm};
        if (duel_out_allowed("node world", "--lcm-log", log_path, &log_kind, force, &world_file, 1) != 0)
            return 2;
    }
    lcm = duel_node_lcm(url);
    if (lcm == NULL)
        return 2;
    if (log_path != NULL) {
        if (duel_lcm_rec_open(&rec, log_path, err_text, sizeof err_text) != 0) {
            fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err_text));
            lcm_destroy(lcm);
            return 2;
        }
        o.rec = &rec;
    }
    err = duel_node_world_run(lcm, &o, &r);
    lcm_destroy(lcm);
    if (r.ignored)
        fprintf(stderr, "duel_evolve: node world: ignored %lu malformed message%s; the first: %s\n",
                (unsigned long)r.ignored, r.ignored == 1 ? "" : "s", r.ignored_msg);
    /* a game lost by forfeit is a game: its log is kept */
    if (o.rec != NULL && duel_lcm_rec_close(&rec, err == 0 || r.forfeit != 0, err_text, sizeof err_text) != 0) {
        fprintf(stderr, "duel_evolve: %s\n", duel_esc_msg(err_text));
        return 1;
    }
    if (err) {
        fprintf(stderr, "duel_evolve: node world: %s\n", r.msg);
        return duel_node_status(err);
    }
    if (o.food_config < 0)
        printf("training food, west %s, east %s\n", duel_text_escape(r.name[0], esc_w, sizeof esc_w),
               duel_text_escape(r.name[1], esc_e, sizeof esc_e));
    else
        printf("food configuration %d, west %s, east %s\n", o.food_config, duel_text_escape(r.name[0], esc_w, sizeof esc_w),
               duel_text_escape(r.name[1], esc_e, sizeof esc_e));
    printf("%s after %u steps\n", duel_lcm_outcome_text(r.res.outcome, r.forfeit), (unsigned)r.res.steps);
    printf("energy: west %.6f, east %.6f; food eaten: west %u, east %u\n", r.res.energy[0] / 65536.0,
           r.res.energy[1] / 65536.0, (unsigned)r.res.eaten[0], (unsigned)r.res.eaten[1]);
    return 0;
}

int duel_cmd_node(int argc, char **argv)
{
    if (argc >= 1 && strcmp(argv[0], "controller") == 0)
        return duel_node_controller_cmd(argc - 1, argv + 1);
    if (argc >= 1 && strcmp(argv[0], "world") == 0)
        return duel_node_world_cmd(argc - 1, argv + 1);
    if (argc >= 1) {
        fprintf(stderr, "duel_evolve: unknown node '%s' (controller, world)\n", duel_esc(argv[0]));
        return 2;
    }
    duel_node_usage();
    return 2;
}
