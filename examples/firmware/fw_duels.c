/* fw_duels.c - the duel set of the firmware example: champions loaded into an arena, games against the built-in strategies, one line each. */
#include "fw_duels.h"

#include "fw_port.h"

/* ---- lines ---------------------------------------------------------------- */

static void fw_line_char(fw_line *l, char c)
{
    if (l->n < FW_LINE_MAX - 1)
        l->s[l->n++] = c;
}

void fw_line_str(fw_line *l, const char *s)
{
    while (*s != '\0')
        fw_line_char(l, *s++);
}

/* v in decimal with at least `digits` digits (zero padded) */
static void fw_line_udec_pad(fw_line *l, uint32_t v, unsigned digits)
{
    char d[10];
    unsigned n = 0;
    do {
        d[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0);
    while (digits > n) {
        fw_line_char(l, '0');
        digits--;
    }
    while (n > 0)
        fw_line_char(l, d[--n]);
}

void fw_line_udec(fw_line *l, uint32_t v)
{
    fw_line_udec_pad(l, v, 1);
}

void fw_line_dec(fw_line *l, int32_t v)
{
    if (v < 0) {
        fw_line_char(l, '-');
        fw_line_udec(l, 0u - (uint32_t)v);
    } else {
        fw_line_udec(l, (uint32_t)v);
    }
}

void fw_line_hex32(fw_line *l, uint32_t v)
{
    int shift;
    fw_line_str(l, "0x");
    for (shift = 28; shift >= 0; shift -= 4)
        fw_line_char(l, "0123456789abcdef"[(v >> shift) & 15u]);
}

void fw_line_q16(fw_line *l, int32_t v)
{
    uint32_t a = v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
    uint32_t ip = a >> 16;
    /* frac / 65536 * 10^6 = frac * 15625 / 1024: 32 bits suffice */
    uint32_t scaled = (a & 0xFFFFu) * 15625u;
    uint32_t q = scaled >> 10, r = scaled & 1023u;
    if (r > 512u || (r == 512u && (q & 1u)))
        q++;
    if (q == 1000000u) {
        q = 0;
        ip++;
    }
    if (v < 0)
        fw_line_char(l, '-');
    fw_line_udec(l, ip);
    fw_line_char(l, '.');
    fw_line_udec_pad(l, q, 6);
}

void fw_line_end(fw_line *l, fw_write_fn write, void *ud)
{
    l->s[l->n++] = '\n'; /* n <= FW_LINE_MAX - 1 */
    write(ud, l->s, l->n);
    l->n = 0;
}

const char *fw_nrt_error_name(int err)
{
    static const char *const names[] = {"NRT_OK",      "NRT_E_ARG",   "NRT_E_TRUNCATED", "NRT_E_MAGIC",
                                        "NRT_E_VERSION", "NRT_E_HEADER", "NRT_E_COUNTS",  "NRT_E_CRC",
                                        "NRT_E_INDEX", "NRT_E_ORDER", "NRT_E_NOMEM",     "NRT_E_TRAILING",
                                        "NRT_E_WEIGHT"};
    if (err > 0 || -err >= (int)(sizeof names / sizeof names[0]))
        return "?";
    return names[-err];
}

/* ---- hashing every motor output through the trace callback ---------------- */

#define FW_FNV_BASIS 2166136261u
#define FW_FNV_PRIME 16777619u

typedef struct fw_hash {
    uint32_t game; /* this game's outputs */
    uint32_t all;  /* every game's outputs so far */
} fw_hash;

static uint32_t fw_fnv_q15(uint32_t h, nrt_q15 v)
{
    uint16_t u = (uint16_t)v;
    h = (h ^ (u & 0xFFu)) * FW_FNV_PRIME;
    return (h ^ (uint32_t)(u >> 8)) * FW_FNV_PRIME;
}

static void fw_hash_trace(void *ud, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                          const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev)
{
    fw_hash *h = (fw_hash *)ud;
    int side, k;
    (void)w;
    (void)in;
    (void)ev;
    for (side = 0; side < 2; side++)
        for (k = 0; k < DUEL_N_OUTPUTS; k++) {
            h->game = fw_fnv_q15(h->game, out[side][k]);
            h->all = fw_fnv_q15(h->all, out[side][k]);
        }
}

/* ---- champions ------------------------------------------------------------ */

static uint32_t fw_rd32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Loads champion `which` (0 = A, 1 = B) into the arena after *used bytes and
 * prints its line, or why it was refused. Returns 0 or FW_EXIT_REFUSED. */
static int fw_load(nrt_net *net, int which, const uint8_t *blob, size_t len, uint8_t *arena, size_t arena_len,
                   size_t *used, fw_write_fn write, void *ud)
{
    fw_line l;
    size_t need = 0;
    int err;

    l.n = 0;
    fw_line_str(&l, which == 0 ? "champion A: " : "champion B: ");
    err = nrt_mem_required(blob, len, &need);
    if (!err)
        err = nrt_load(net, blob, len, arena + *used, arena_len - *used);
    if (err) {
        if (err == NRT_E_NOMEM) {
            fw_line_str(&l, "needs ");
            fw_line_udec(&l, (uint32_t)need);
            fw_line_str(&l, " bytes of RAM, ");
            fw_line_udec(&l, (uint32_t)(arena_len - *used));
            fw_line_str(&l, " left in the arena: ");
        }
        fw_line_str(&l, "refused by the runtime: error ");
        fw_line_dec(&l, err);
        fw_line_char(&l, ' ');
        fw_line_str(&l, fw_nrt_error_name(err));
        fw_line_end(&l, write, ud);
        return FW_EXIT_REFUSED;
    }
    *used += need;
    fw_line_udec(&l, (uint32_t)len);
    fw_line_str(&l, " bytes, crc ");
    fw_line_hex32(&l, fw_rd32(blob + NRT_OFF_CRC));
    fw_line_str(&l, ", ");
    fw_line_udec(&l, net->n_inputs);
    fw_line_str(&l, " inputs, ");
    fw_line_udec(&l, net->n_outputs);
    fw_line_str(&l, " outputs, ");
    fw_line_udec(&l, net->n_hidden);
    fw_line_str(&l, " hidden, ");
    fw_line_udec(&l, net->n_conns);
    fw_line_str(&l, " connections, ");
    fw_line_udec(&l, (uint32_t)need);
    fw_line_str(&l, " bytes of RAM");
    if (net->n_inputs != DUEL_N_INPUTS || net->n_outputs != DUEL_N_OUTPUTS) {
        fw_line_str(&l, ": not a duel network (13 inputs, 3 outputs)");
        err = FW_EXIT_REFUSED;
    }
    fw_line_end(&l, write, ud);
    return err;
}

/* ---- the games ------------------------------------------------------------ */

/* Players: 0 = A, 1 = B, FW_BUILTIN + k = builtin k. */
#define FW_BUILTIN 2
#define FW_FOODS 6
static const int16_t fw_foods[FW_FOODS] = {DUEL_TRAINING, 0, 23, 58, 101, 143};
static const uint8_t fw_opponents[3] = {DUEL_FORAGER_HUNTER, DUEL_HUNTER, DUEL_FORAGER};

/* Game g (0 .. FW_DUELS_GAMES - 1): who plays west and east, on which food. */
static void fw_game(int g, int *west, int *east, int *food)
{
    if (g < 4 * FW_FOODS) {
        /* each champion, each food, the champion west then east */
        int champ = g / (2 * FW_FOODS), i = (g / 2) % FW_FOODS, other = FW_BUILTIN + fw_opponents[i % 3];
        *food = fw_foods[i];
        *west = g % 2 == 0 ? champ : other;
        *east = g % 2 == 0 ? other : champ;
    } else {
        /* A against B, both sides */
        *food = 77;
        *west = g % 2 == 0 ? 0 : 1;
        *east = 1 - *west;
    }
}

static void fw_player_name(fw_line *l, int p)
{
    if (p < FW_BUILTIN) {
        fw_line_str(l, p == 0 ? "A" : "B");
    } else {
        fw_line_str(l, "builtin:");
        fw_line_str(l, duel_builtin_name(p - FW_BUILTIN));
    }
}

static const char *fw_outcome_text(int outcome)
{
    switch (outcome) {
    case DUEL_WEST_WINS: return "west wins";
    case DUEL_EAST_WINS: return "east wins";
    case DUEL_DRAW: return "draw";
    case DUEL_TIMEOUT: return "timeout";
    default: return "unfinished";
    }
}

int fw_duels_run(const uint8_t *const blob[2], const size_t blob_len[2], const uint8_t *world, size_t world_len,
                 void *arena, size_t arena_len, fw_write_fn write, void *ud)
{
#ifdef FW_WORLD
    duel_rules rules;
#endif
    nrt_net net[2];
    duel_controller builtin[DUEL_N_BUILTINS], champ[2];
    fw_hash h;
    fw_line l;
    size_t used = 0;
    uint32_t won[3] = {0, 0, 0}, draws = 0, timeouts = 0;
    int g, i, rc;

    l.n = 0;
#ifdef FW_WORLD
    if (world != NULL) {
        size_t off = 0;
        uint64_t id;
        if (duel_rules_decode(&rules, world, world_len, &off) != DUEL_OK) {
            fw_line_str(&l, "world rules refused at byte ");
            fw_line_udec(&l, (uint32_t)off);
            fw_line_end(&l, write, ud);
            return FW_EXIT_REFUSED;
        }
        id = duel_rules_id(&rules);
        fw_line_str(&l, "neat-duel firmware duels: world ");
        fw_line_hex32(&l, (uint32_t)(id >> 32));
        fw_line_hex32(&l, (uint32_t)id);
    } else
#else
    /* world v1 only: a build without FW_WORLD links none of the rules' decoding */
    (void)world;
    (void)world_len;
#endif
    {
        fw_line_str(&l, "neat-duel firmware duels: duel spec v");
        fw_line_udec(&l, DUEL_SPEC_VERSION);
    }
    fw_line_str(&l, ", runtime ");
    fw_line_udec(&l, NRT_VERSION_MAJOR);
    fw_line_char(&l, '.');
    fw_line_udec(&l, NRT_VERSION_MINOR);
    fw_line_str(&l, ", blob format ");
    fw_line_udec(&l, NRT_FORMAT_VERSION);
    fw_line_end(&l, write, ud);
    for (i = 0; i < 2; i++) {
        rc = fw_load(&net[i], i, blob[i], blob_len[i], (uint8_t *)arena, arena_len, &used, write, ud);
        if (rc)
            return rc;
        champ[i].net = &net[i];
        champ[i].builtin = 0;
    }
    for (i = 0; i < DUEL_N_BUILTINS; i++) {
        builtin[i].net = NULL;
        builtin[i].builtin = i;
    }

    h.all = FW_FNV_BASIS;
    for (g = 0; g < FW_DUELS_GAMES; g++) {
        int west, east, food, err;
        duel_result r;
        duel_controller *cw, *ce;

        fw_game(g, &west, &east, &food);
        cw = west < FW_BUILTIN ? &champ[west] : &builtin[west - FW_BUILTIN];
        ce = east < FW_BUILTIN ? &champ[east] : &builtin[east - FW_BUILTIN];
        h.game = FW_FNV_BASIS;
#ifdef FW_WORLD
        err = world != NULL ? duel_play_rules(&rules, cw, ce, food, &r, fw_hash_trace, &h)
                            : duel_play(cw, ce, food, &r, fw_hash_trace, &h);
#else
        err = duel_play(cw, ce, food, &r, fw_hash_trace, &h);
#endif

        fw_line_str(&l, "game ");
        fw_line_udec_pad(&l, (uint32_t)g + 1u, 2);
        fw_line_str(&l, " food ");
        if (food == DUEL_TRAINING)
            fw_line_str(&l, "training");
        else
            fw_line_udec(&l, (uint32_t)food);
        fw_line_str(&l, ": west ");
        fw_player_name(&l, west);
        fw_line_str(&l, ", east ");
        fw_player_name(&l, east);
        if (err) {
            fw_line_str(&l, " -> duel_play failed: error ");
            fw_line_dec(&l, err);
            fw_line_end(&l, write, ud);
            return FW_EXIT_FAILED;
        }
        fw_line_str(&l, " -> ");
        fw_line_str(&l, fw_outcome_text(r.outcome));
        fw_line_str(&l, " after ");
        fw_line_udec(&l, r.steps);
        fw_line_str(&l, " steps; energy ");
        fw_line_q16(&l, r.energy[DUEL_WEST]);
        fw_line_char(&l, ' ');
        fw_line_q16(&l, r.energy[DUEL_EAST]);
        fw_line_str(&l, "; eaten ");
        fw_line_udec(&l, r.eaten[DUEL_WEST]);
        fw_line_char(&l, ' ');
        fw_line_udec(&l, r.eaten[DUEL_EAST]);
        fw_line_str(&l, "; outputs ");
        fw_line_hex32(&l, h.game);
        fw_line_end(&l, write, ud);

        if (r.outcome == DUEL_DRAW) {
            draws++;
        } else if (r.outcome == DUEL_TIMEOUT) {
            timeouts++;
        } else {
            int winner = r.outcome == DUEL_WEST_WINS ? west : east;
            won[winner < FW_BUILTIN ? winner : 2]++;
        }
    }
    fw_line_udec(&l, FW_DUELS_GAMES);
    fw_line_str(&l, " games: A won ");
    fw_line_udec(&l, won[0]);
    fw_line_str(&l, ", B won ");
    fw_line_udec(&l, won[1]);
    fw_line_str(&l, ", builtins won ");
    fw_line_udec(&l, won[2]);
    fw_line_str(&l, ", draws ");
    fw_line_udec(&l, draws);
    fw_line_str(&l, ", timeouts ");
    fw_line_udec(&l, timeouts);
    fw_line_str(&l, "; all outputs ");
    fw_line_hex32(&l, h.all);
    fw_line_end(&l, write, ud);
    return FW_EXIT_OK;
}
