/* run_engine.c - a duel coevolution from C with libduelengine: each generation printed, the run directory the
 * same as duel_evolve run's (duel_evolve resume continues it). Usage: run_engine CONFIG.ini OUT_DIR */
#include <stdio.h>

#include "duel_engine.h"

static void on_say(void *ud, duel_say_kind kind, const char *text)
{
    (void)ud, (void)kind;
    fprintf(stderr, "run_engine: %s\n", text);
}

static void on_generation(void *ud, const duel_engine_record *r)
{
    (void)ud;
    printf("generation %u of %u: %u dominance levels; %s", r->generation + 1, r->generations, r->dominants,
           r->generations_rows);
}

int main(int argc, char **argv)
{
    duel_config cfg;
    duel_engine_options o = {0};
    duel_engine *run;
    char err[600];
    int status;
    duel_config_default(&cfg);
    if (argc != 3 || duel_config_read(&cfg, argv[1], err, sizeof err) || duel_config_check(&cfg, err, sizeof err))
        return fprintf(stderr, "run_engine: %s\n", argc != 3 ? "usage: run_engine CONFIG.ini OUT_DIR" : err), 2;
    o.hooks.say = on_say;
    o.hooks.generation = on_generation;
    if ((status = duel_engine_new(&run, &cfg, argv[2], &o)) != DUEL_ENGINE_OK)
        return status;
    status = duel_engine_step(run, 0); /* 0: to the configuration's last generation */
    return status == DUEL_ENGINE_OK ? duel_engine_close(run) : (duel_engine_close(run), status);
}
