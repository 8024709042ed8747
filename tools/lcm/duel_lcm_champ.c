/* duel_lcm_champ.c - a generation champion's comparison games on the training food, from both sides, recorded as LCM event logs. */
#include <stdio.h>

#include "duel_lcm.h"
#include "duel_lcm_champ.h"
#include "neat_phenotype.h"
#include "duel_text.h"

int duel_lcm_record_champion_games(const char *dir, uint32_t generation, uint32_t champion_pop,
                                   const neat_genome *champion, const neat_genome *other, const neat_params *p,
                                   const duel_rules *rules, char *msg, size_t cap)
{
    neat_phenotype ph[2];
    duel_controller c[2];
    duel_result res;
    char path[4200], err[4400], name[2][64];
    int side, e, rc = 0;

    neat_phenotype_init(&ph[0], NULL);
    neat_phenotype_init(&ph[1], NULL);
    snprintf(name[0], sizeof name[0], "champions/gen-%05u.blob", (unsigned)generation);
    snprintf(name[1], sizeof name[1], "gen-%05u best of %c", (unsigned)generation, champion_pop ? 'A' : 'B');
    e = neat_phenotype_load(&ph[0], champion, p);
    if (!e)
        e = neat_phenotype_load(&ph[1], other, p);
    if (e) {
        snprintf(msg, cap, "generation %u: cannot load the champion's game networks (%d)", (unsigned)generation, e);
        rc = -1;
    }
    for (side = 0; side < 2 && rc == 0; side++) {
        /* side 0: the champion west; side 1: east */
        int w = side, east = side ^ 1;
        c[0].net = &ph[w].net;
        c[0].builtin = 0;
        c[1].net = &ph[east].net;
        c[1].builtin = 0;
        snprintf(path, sizeof path, "%s/games/gen-%05u-%s.lcm", dir, (unsigned)generation, side ? "east" : "west");
        if (duel_lcm_record_game(path, rules, &c[0], &c[1], DUEL_TRAINING, name[w], name[east], &res, err,
                                 sizeof err) != 0) {
            snprintf(msg, cap, "%s", err);
            rc = -1;
        }
    }
    neat_phenotype_free(&ph[0]);
    neat_phenotype_free(&ph[1]);
    return rc;
}
