/* duel_lcm_champ_none.c - `--record-champion-games` in a build without LCM (the Python package): refused with one line. */
#include <stdio.h>

#include "duel_lcm_champ.h"
#include "duel_text.h"

int duel_lcm_record_champion_games(const char *dir, uint32_t generation, uint32_t champion_pop,
                                   const neat_genome *champion, const neat_genome *other, const neat_params *p,
                                   const duel_rules *rules, char *msg, size_t cap)
{
    char esc[1100];
    (void)generation, (void)champion_pop, (void)champion, (void)other, (void)p, (void)rules;
    snprintf(msg, cap, "%s: --record-champion-games needs a build with LCM (duel_evolve itself)",
             duel_text_escape(dir, esc, sizeof esc));
    return -1;
}
