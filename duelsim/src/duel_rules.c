/* duel_rules.c - the world's chosen rules as data: world v1's values, the checks that make a game possible, canonical bytes and identity. */
#include <string.h>

#include "duel_internal.h"

#define Q(v) ((int32_t)(v) * DUEL_ONE)

/* docs/duel-world.md, version 1: every value the simulator had as a constant */
const duel_rules duel_v1_rules = {
    Q(DUEL_RADIUS),
    {Q(100), Q(500)},
    {Q(300), Q(300)},
    {DUEL_HALF_TURN, 0u},
    Q(DUEL_START_ENERGY),
    Q(DUEL_FOOD_ENERGY),
    Q(DUEL_EAT_DIST),
    0,
    DUEL_TRAIN_FOOD,
    /* training item i at (200 + 100 (i mod 3), 200 + 100 (i div 3)) */
    {Q(200), Q(300), Q(400), Q(200), Q(300), Q(400), Q(200), Q(300), Q(400)},
    {Q(200), Q(200), Q(200), Q(300), Q(300), Q(300), Q(400), Q(400), Q(400)},
    /* candidate j at (X[j div 4], Y[j mod 4]), X = {60, 140, 220}, Y = {75, 225, 375, 525} */
    {Q(60), Q(60), Q(60), Q(60), Q(140), Q(140), Q(140), Q(140), Q(220), Q(220), Q(220), Q(220)},
    {Q(75), Q(225), Q(375), Q(525), Q(75), Q(225), Q(375), Q(525), Q(75), Q(225), Q(375), Q(525)},
    850,
    850,
    200,
    200,
};

const duel_rules *duel_rules_v1(void)
{
    return &duel_v1_rules;
}

static const struct {
    const char *name;
    const duel_rules *rules;
} duel_named[] = {{"v1", &duel_v1_rules}};
#define DUEL_N_NAMED (sizeof duel_named / sizeof duel_named[0])

const duel_rules *duel_rules_named(const char *name)
{
    size_t i;
    for (i = 0; name != NULL && i < DUEL_N_NAMED; i++)
        if (strcmp(name, duel_named[i].name) == 0)
            return duel_named[i].rules;
    return NULL;
}

const char *duel_rules_name(const duel_rules *r)
{
    size_t i;
    for (i = 0; r != NULL && i < DUEL_N_NAMED; i++)
        if (duel_rules_equal(r, duel_named[i].rules))
            return duel_named[i].name;
    return NULL;
}

/* ---- checks ---- */

/* the fields' byte offsets in the canonical bytes (below), for the decoder's messages */
#define DUEL_OFF_RADIUS 8u
#define DUEL_OFF_START (DUEL_OFF_RADIUS + 4u)
#define DUEL_OFF_ENERGY (DUEL_OFF_START + 24u)
#define DUEL_OFF_FOOD_ENERGY (DUEL_OFF_ENERGY + 4u)
#define DUEL_OFF_EAT (DUEL_OFF_FOOD_ENERGY + 4u)
#define DUEL_OFF_SHARE (DUEL_OFF_EAT + 4u)
#define DUEL_OFF_TRAIN (DUEL_OFF_SHARE + 4u)
#define DUEL_OFF_CAND (DUEL_OFF_TRAIN + 4u + 8u * DUEL_MAX_TRAIN_FOOD)
#define DUEL_OFF_RANGES (DUEL_OFF_CAND + 8u * DUEL_CANDIDATES)
#define DUEL_OFF_CRC (DUEL_OFF_RANGES + 8u)


/* The limits: energies stay far inside int32 (start + 11 items at most
 * 10000 + 11 x 1000 units, less at most 1178 units of costs in 750 steps:
 * every energy, and every difference of two plus a scale, is below 2^31 in
 * Q16.16); the
 * eating distance below the board's quarter, so that the sensing's test of
 * "no item near" stays an exact bound (duel_food_near_limit) */
#define DUEL_MAX_RADIUS Q(100)
#define DUEL_MAX_START_ENERGY Q(10000)
#define DUEL_MAX_FOOD_ENERGY Q(1000)
#define DUEL_MAX_EAT Q(150)

static int duel_on_board(int32_t x, int32_t y)
{
    return x >= 0 && x <= Q(DUEL_BOARD) && y >= 0 && y <= Q(DUEL_BOARD);
}

/* An item within the eating distance of a start position would be eaten
 * before either robot could sense it (an object at a robot's centre gives
 * no reading), and would make the first step a lottery of the rounding. */
static int duel_under_start(const duel_rules *r, int32_t x, int32_t y)
{
    int side;
    for (side = 0; side < 2; side++)
        if (duel_dist2(r->start_x[side], r->start_y[side], x, y) < (int64_t)r->eat_dist * r->eat_dist)
            return 1;
    return 0;
}

/* duel_rules_check, and the failing field's offset in the canonical bytes */
static int duel_rules_check_at(const duel_rules *r, const char **field, const char **why, size_t *offset)
{
    const char *f = NULL, *w = NULL;
    size_t o = 0;
    int side;
    uint32_t i;
    if (r == NULL) {
        f = "rules";
        o = 0;
        w = "no rules given";
        goto bad;
    }
    if (r->radius < DUEL_ONE || r->radius > DUEL_MAX_RADIUS) {
        f = "radius";
        o = DUEL_OFF_RADIUS;
        w = "must be 1 to 100";
        goto bad;
    }
    for (side = 0; side < 2; side++) {
        int32_t lo = r->radius, hi = Q(DUEL_BOARD) - r->radius;
        if (r->start_x[side] < lo || r->start_x[side] > hi || r->start_y[side] < lo || r->start_y[side] > hi) {
            f = side == 0 ? "start_west" : "start_east";
            o = DUEL_OFF_START + 12u * (size_t)side;
            w = "the robot would start inside a wall (its centre must be at least radius from every edge)";
            goto bad;
        }
    }
    if (duel_dist2(r->start_x[0], r->start_y[0], r->start_x[1], r->start_y[1]) <
        (int64_t)Q(DUEL_COLLIDE_DIST) * Q(DUEL_COLLIDE_DIST)) {
        f = "start_east";
        o = DUEL_OFF_START + 12u;
        w = "the robots would start within the collision distance 20 of each other";
        goto bad;
    }
    if (r->start_energy < DUEL_ONE || r->start_energy > DUEL_MAX_START_ENERGY) {
        f = "start_energy";
        o = DUEL_OFF_ENERGY;
        w = "must be 1 to 10000";
        goto bad;
    }
    if (r->food_energy < 0 || r->food_energy > DUEL_MAX_FOOD_ENERGY) {
        f = "food_energy";
        o = DUEL_OFF_FOOD_ENERGY;
        w = "must be 0 to 1000";
        goto bad;
    }
    if (r->eat_dist < DUEL_ONE || r->eat_dist > DUEL_MAX_EAT) {
        f = "eat_dist";
        o = DUEL_OFF_EAT;
        w = "must be 1 to 150";
        goto bad;
    }
    if (r->share_dist < 0 || r->share_dist > r->eat_dist) {
        f = "share_dist";
        o = DUEL_OFF_SHARE;
        w = "must be 0 to eat_dist";
        goto bad;
    }
    if (r->n_train > DUEL_MAX_TRAIN_FOOD) {
        f = "train_food";
        o = DUEL_OFF_TRAIN;
        w = "more than 9 items (a comparison layout adds 2 to the 11 a world holds)";
        goto bad;
    }
    for (i = 0; i < r->n_train; i++) {
        if (!duel_on_board(r->train_x[i], r->train_y[i])) {
            f = "train_food";
            o = DUEL_OFF_TRAIN;
            w = "an item off the board (x and y must be 0 to 600)";
            goto bad;
        }
        if (duel_under_start(r, r->train_x[i], r->train_y[i])) {
            f = "train_food";
            o = DUEL_OFF_TRAIN;
            w = "an item within eat_dist of a robot's start";
            goto bad;
        }
    }
    for (i = 0; i < DUEL_CANDIDATES; i++) {
        if (!duel_on_board(r->cand_x[i], r->cand_y[i])) {
            f = "candidates";
            o = DUEL_OFF_CAND;
            w = "a position off the board (x and y must be 0 to 600)";
            goto bad;
        }
        if (duel_under_start(r, r->cand_x[i], r->cand_y[i]) ||
            duel_under_start(r, Q(DUEL_BOARD) - r->cand_x[i], r->cand_y[i])) {
            f = "candidates";
            o = DUEL_OFF_CAND;
            w = "a position (or its mirror) within eat_dist of a robot's start";
            goto bad;
        }
    }
    if (r->food_range == 0) {
        f = "food_range";
        o = DUEL_OFF_RANGES;
        w = "must be 1 to 65535";
        goto bad;
    }
    if (r->robot_range == 0) {
        f = "robot_range";
        o = DUEL_OFF_RANGES + 2u;
        w = "must be 1 to 65535";
        goto bad;
    }
    if (r->energy_scale == 0) {
        f = "energy_scale";
        o = DUEL_OFF_RANGES + 4u;
        w = "must be 1 to 65535";
        goto bad;
    }
    if (r->wall_range == 0) {
        f = "wall_range";
        o = DUEL_OFF_RANGES + 6u;
        w = "must be 1 to 65535";
        goto bad;
    }
    return DUEL_OK;
bad:
    if (field != NULL)
        *field = f;
    if (why != NULL)
        *why = w;
    if (offset != NULL)
        *offset = o;
    return DUEL_E_RULES;
}

int duel_rules_check(const duel_rules *r, const char **field, const char **why)
{
    return duel_rules_check_at(r, field, why, NULL);
}

/* ---- canonical bytes ----
 * "DRUL", u16 version 1, u16 length, then the fields in declaration order
 * (little endian; every training slot, unused ones zero), then the CRC-32
 * of every byte before it (docs/formats.md). */
#define DUEL_RULES_VERSION 1

static uint8_t *duel_put32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
    return p + 4;
}

static uint8_t *duel_put16(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    return p + 2;
}

static uint32_t duel_get32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static uint16_t duel_get16(const uint8_t *p)
{
    return (uint16_t)(p[0] | p[1] << 8);
}

typedef char duel_rules_bytes_check[DUEL_OFF_CRC + 4u == DUEL_RULES_BYTES ? 1 : -1];

int duel_rules_encode(const duel_rules *r, uint8_t out[DUEL_RULES_BYTES])
{
    uint8_t *p = out;
    uint32_t i;
    int side;
    if (duel_rules_check(r, NULL, NULL) != DUEL_OK || out == NULL)
        return out == NULL ? DUEL_E_ARG : DUEL_E_RULES;
    memcpy(p, "DRUL", 4);
    p = duel_put16(p + 4, DUEL_RULES_VERSION);
    p = duel_put16(p, DUEL_RULES_BYTES);
    p = duel_put32(p, (uint32_t)r->radius);
    for (side = 0; side < 2; side++) {
        p = duel_put32(p, (uint32_t)r->start_x[side]);
        p = duel_put32(p, (uint32_t)r->start_y[side]);
        p = duel_put32(p, r->start_heading[side]);
    }
    p = duel_put32(p, (uint32_t)r->start_energy);
    p = duel_put32(p, (uint32_t)r->food_energy);
    p = duel_put32(p, (uint32_t)r->eat_dist);
    p = duel_put32(p, (uint32_t)r->share_dist);
    p = duel_put32(p, r->n_train);
    for (i = 0; i < DUEL_MAX_TRAIN_FOOD; i++) {
        p = duel_put32(p, i < r->n_train ? (uint32_t)r->train_x[i] : 0u);
        p = duel_put32(p, i < r->n_train ? (uint32_t)r->train_y[i] : 0u);
    }
    for (i = 0; i < DUEL_CANDIDATES; i++) {
        p = duel_put32(p, (uint32_t)r->cand_x[i]);
        p = duel_put32(p, (uint32_t)r->cand_y[i]);
    }
    p = duel_put16(p, r->food_range);
    p = duel_put16(p, r->robot_range);
    p = duel_put16(p, r->energy_scale);
    p = duel_put16(p, r->wall_range);
    duel_put32(p, nrt_crc32(0, out, DUEL_OFF_CRC));
    return DUEL_OK;
}

int duel_rules_decode(duel_rules *r, const uint8_t *bytes, size_t len, size_t *offset)
{
    const uint8_t *p;
    const char *field = NULL;
    size_t bad = 0;
    uint32_t i;
    int side;
    duel_rules got;
    if (r == NULL || bytes == NULL)
        return DUEL_E_ARG;
    /* nothing is read past what was given: the size first */
    if (len < 8u || bytes[0] != 'D' || bytes[1] != 'R' || bytes[2] != 'U' || bytes[3] != 'L')
        goto fail;
    bad = 4;
    if (duel_get16(bytes + 4) != DUEL_RULES_VERSION)
        goto fail;
    bad = 6;
    if (duel_get16(bytes + 6) != DUEL_RULES_BYTES || len != DUEL_RULES_BYTES) {
        bad = len < DUEL_RULES_BYTES || duel_get16(bytes + 6) != DUEL_RULES_BYTES ? 6u : DUEL_RULES_BYTES;
        goto fail;
    }
    bad = DUEL_OFF_CRC;
    if (duel_get32(bytes + DUEL_OFF_CRC) != nrt_crc32(0, bytes, DUEL_OFF_CRC))
        goto fail;
    memset(&got, 0, sizeof got);
    p = bytes + DUEL_OFF_RADIUS;
    got.radius = (int32_t)duel_get32(p);
    p += 4;
    for (side = 0; side < 2; side++, p += 12) {
        got.start_x[side] = (int32_t)duel_get32(p);
        got.start_y[side] = (int32_t)duel_get32(p + 4);
        got.start_heading[side] = duel_get32(p + 8);
    }
    got.start_energy = (int32_t)duel_get32(p);
    got.food_energy = (int32_t)duel_get32(p + 4);
    got.eat_dist = (int32_t)duel_get32(p + 8);
    got.share_dist = (int32_t)duel_get32(p + 12);
    got.n_train = duel_get32(p + 16);
    p += 20;
    for (i = 0; i < DUEL_MAX_TRAIN_FOOD; i++, p += 8) {
        got.train_x[i] = (int32_t)duel_get32(p);
        got.train_y[i] = (int32_t)duel_get32(p + 4);
        /* canonical: unused slots are zero */
        if (i >= got.n_train && (got.train_x[i] != 0 || got.train_y[i] != 0) && got.n_train <= DUEL_MAX_TRAIN_FOOD) {
            bad = (size_t)(p - bytes);
            goto fail;
        }
    }
    for (i = 0; i < DUEL_CANDIDATES; i++, p += 8) {
        got.cand_x[i] = (int32_t)duel_get32(p);
        got.cand_y[i] = (int32_t)duel_get32(p + 4);
    }
    got.food_range = duel_get16(p);
    got.robot_range = duel_get16(p + 2);
    got.energy_scale = duel_get16(p + 4);
    got.wall_range = duel_get16(p + 6);
    if (duel_rules_check_at(&got, &field, NULL, &bad) != DUEL_OK)
        goto fail;
    *r = got;
    return DUEL_OK;
fail:
    if (offset != NULL)
        *offset = bad;
    return DUEL_E_RULES;
}

uint64_t duel_rules_id(const duel_rules *r)
{
    uint8_t b[DUEL_RULES_BYTES];
    uint64_t h = 14695981039346656037ull;
    size_t i;
    if (duel_rules_encode(r, b) != DUEL_OK)
        return 0;
    for (i = 0; i < DUEL_OFF_CRC; i++) {
        h ^= b[i];
        h *= 1099511628211ull;
    }
    return h;
}

int duel_rules_equal(const duel_rules *a, const duel_rules *b)
{
    uint8_t ea[DUEL_RULES_BYTES], eb[DUEL_RULES_BYTES];
    if (duel_rules_encode(a, ea) != DUEL_OK || duel_rules_encode(b, eb) != DUEL_OK)
        return 0;
    return memcmp(ea, eb, DUEL_OFF_CRC) == 0;
}
