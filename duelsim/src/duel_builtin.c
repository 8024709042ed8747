/* duel_builtin.c - hand-coded strategies (not networks) reading the same 13 sensors: a fixed ladder to measure champions against. */
#include <string.h>

#include "duel.h"

static const char *const duel_builtin_names[DUEL_N_BUILTINS] = {"idle", "spinner", "forager", "hunter",
                                                                 "forager-hunter"};

int duel_builtin_parse(const char *name)
{
    int i;
    for (i = 0; name != NULL && i < DUEL_N_BUILTINS; i++)
        if (strcmp(name, duel_builtin_names[i]) == 0)
            return i;
    return DUEL_E_ARG;
}

const char *duel_builtin_name(int builtin)
{
    return builtin >= 0 && builtin < DUEL_N_BUILTINS ? duel_builtin_names[builtin] : NULL;
}

/* the sector (0..4) with the strongest reading among in[first..first+4], -1 if none */
static int duel_strongest(const nrt_q15 *in, int first)
{
    int k, best = -1;
    for (k = 0; k < 5; k++)
        if (in[first + k] > 0 && (best < 0 || in[first + k] > in[first + best]))
            best = k;
    return best;
}

static void duel_set(nrt_q15 out[DUEL_N_OUTPUTS], nrt_q15 l, nrt_q15 r, nrt_q15 f)
{
    out[0] = l;
    out[1] = r;
    out[2] = f;
}

/* head for whatever is in sector k: straight on for 0, turn toward 1-2 (left) or 3-4 (right) */
static void duel_steer_to(int k, nrt_q15 out[DUEL_N_OUTPUTS])
{
    switch (k) {
    case 0: duel_set(out, 0, 0, NRT_ONE); break;
    case 1: duel_set(out, NRT_ONE, 0, NRT_ONE / 2); break;
    case 2: duel_set(out, NRT_ONE, 0, 0); break;
    case 3: duel_set(out, 0, NRT_ONE, 0); break;
    default: duel_set(out, 0, NRT_ONE, NRT_ONE / 2); break;
    }
}

/* run from whatever is in sector k: turn away at full speed */
static void duel_steer_away(int k, nrt_q15 out[DUEL_N_OUTPUTS])
{
    if (k == 1 || k == 2)
        duel_set(out, 0, NRT_ONE, NRT_ONE);
    else if (k == 3 || k == 4)
        duel_set(out, NRT_ONE, 0, NRT_ONE);
    else if (k == 0)
        duel_set(out, NRT_ONE, 0, NRT_ONE);
    else
        duel_set(out, 0, 0, NRT_ONE);
}

static void duel_forage(const nrt_q15 in[DUEL_N_INPUTS], nrt_q15 out[DUEL_N_OUTPUTS])
{
    int k = duel_strongest(in, 1);
    if (k >= 0)
        duel_steer_to(k, out);
    else if (in[12] > NRT_ONE / 2)
        duel_set(out, NRT_ONE, 0, NRT_ONE / 4); /* no food left: wander, turning off walls */
    else
        duel_set(out, 0, 0, NRT_ONE);
}

void duel_builtin_act(int builtin, const nrt_q15 in[DUEL_N_INPUTS], nrt_q15 out[DUEL_N_OUTPUTS])
{
    int robot = duel_strongest(in, 6);
    switch (builtin) {
    case DUEL_SPINNER:
        duel_set(out, NRT_ONE, 0, 0);
        break;
    case DUEL_FORAGER:
        duel_forage(in, out);
        break;
    case DUEL_HUNTER:
        /* chase when ahead on energy, flee otherwise */
        if (in[11] > 0)
            duel_steer_to(robot, out);
        else
            duel_steer_away(robot, out);
        break;
    case DUEL_FORAGER_HUNTER:
        /* forage; attack only when at least 100 energy ahead (in[11] >= 0.5) */
        if (in[11] >= NRT_ONE / 2 && robot >= 0)
            duel_steer_to(robot, out);
        else
            duel_forage(in, out);
        break;
    default: /* DUEL_IDLE and anything unknown: never move */
        duel_set(out, 0, 0, 0);
        break;
    }
}
