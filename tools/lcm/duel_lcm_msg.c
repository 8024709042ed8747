/* duel_lcm_msg.c - duel messages from the world's fixed-point state, and a state message checked and read back into a world. */
#include <stdio.h>
#include <string.h>

#include "duel_lcm.h"

/* the int32 bit pattern of a binary angle, and back (docs/lcm.md) */
static int32_t duel_lcm_angle_out(duel_angle a)
{
    return a >= DUEL_HALF_TURN ? -(int32_t)(~a) - 1 : (int32_t)a;
}

static duel_angle duel_lcm_angle_in(int32_t v)
{
    return (duel_angle)v;
}

/* degrees in (-180, 180] */
static double duel_lcm_degrees(duel_angle a)
{
    if (a == DUEL_HALF_TURN)
        return 180.0;
    return duel_lcm_angle_out(a) * (180.0 / 2147483648.0);
}

void duel_lcm_state_fill(duel_state_t *m, const duel_world *w, const duel_event *prev, int food_config,
                         char *names[2], int forfeit)
{
    int s, i;
    memset(m, 0, sizeof *m);
    m->version = DUEL_STATE_T_VERSION;
    m->step = (int32_t)w->t;
    m->food_config = food_config;
    for (s = 0; s < 2; s++) {
        const duel_robot *r = &w->robot[s];
        m->controller[s] = names[s];
        m->x[s] = r->x;
        m->y[s] = r->y;
        m->heading[s] = duel_lcm_angle_out(r->heading);
        m->energy[s] = r->energy;
        m->eaten[s] = (int8_t)r->eaten;
        m->eaten_by[s] = prev != NULL ? (int32_t)prev->eaten_by[s] : 0;
        m->x_units[s] = r->x / 65536.0;
        m->y_units[s] = r->y / 65536.0;
        m->heading_deg[s] = duel_lcm_degrees(r->heading);
        m->energy_units[s] = r->energy / 65536.0;
    }
    m->n_food = (int8_t)w->n_food;
    for (i = 0; i < DUEL_MAX_FOOD; i++) {
        m->food_x[i] = w->food_x[i];
        m->food_y[i] = w->food_y[i];
    }
    m->food_mask = (int32_t)w->food_mask;
    m->outcome = (int8_t)w->outcome;
    m->forfeit = (int8_t)forfeit;
}

void duel_lcm_world_fill(duel_world_t *m, const duel_rules *r)
{
    memset(m, 0, sizeof *m);
    m->version = DUEL_WORLD_T_VERSION;
    m->identity = (int64_t)duel_rules_id(r);
    duel_rules_encode(r, (uint8_t *)m->rules);
}

void duel_lcm_sense_fill(duel_sense_t *m, int side, uint32_t step, const nrt_q15 in[DUEL_N_INPUTS])
{
    int i;
    memset(m, 0, sizeof *m);
    m->version = DUEL_SENSE_T_VERSION;
    m->side = (int8_t)side;
    m->step = (int32_t)step;
    for (i = 0; i < DUEL_N_INPUTS; i++) {
        m->input[i] = in[i];
        m->value[i] = in[i] / 32768.0;
    }
}

void duel_lcm_motor_fill(duel_motor_t *m, int side, int32_t step, const nrt_q15 out[DUEL_N_OUTPUTS], char *name)
{
    int i;
    memset(m, 0, sizeof *m);
    m->version = DUEL_MOTOR_T_VERSION;
    m->side = (int8_t)side;
    m->step = step;
    for (i = 0; i < DUEL_N_OUTPUTS; i++) {
        m->output[i] = out[i];
        m->value[i] = out[i] / 32768.0;
    }
    m->controller = name;
}

int duel_lcm_state_read(const duel_state_t *m, const duel_rules *rules, duel_world *w, duel_event *ev, char *msg,
                        size_t msg_len)
{
    duel_world ref;
    int s, i;
    uint32_t items;

    if (m->step < 0 || m->step > DUEL_MAX_STEPS) {
        snprintf(msg, msg_len, "state of step %ld, outside 0..%d", (long)m->step, DUEL_MAX_STEPS);
        return -1;
    }
    if (m->food_config < DUEL_TRAINING || m->food_config >= DUEL_CONFIGS) {
        snprintf(msg, msg_len, "food configuration %ld, outside -1..%d", (long)m->food_config, DUEL_CONFIGS - 1);
        return -1;
    }
    if (rules == NULL)
        rules = duel_rules_v1();
    duel_world_init_rules(&ref, rules, m->food_config);
    if (m->n_food != ref.n_food) {
        snprintf(msg, msg_len, "%d food items, configuration %ld has %u", m->n_food, (long)m->food_config,
                 (unsigned)ref.n_food);
        return -1;
    }
    for (i = 0; i < DUEL_MAX_FOOD; i++)
        if (m->food_x[i] != ref.food_x[i] || m->food_y[i] != ref.food_y[i]) {
            snprintf(msg, msg_len, "food item %d not where configuration %ld puts it", i, (long)m->food_config);
            return -1;
        }
    items = (1u << ref.n_food) - 1u;
    if (((uint32_t)m->food_mask & ~items) != 0) {
        snprintf(msg, msg_len, "food mask 0x%lx names items that do not exist", (unsigned long)(uint32_t)m->food_mask);
        return -1;
    }
    if (m->outcome < DUEL_STATE_T_RUNNING || m->outcome > DUEL_STATE_T_TIMEOUT || m->forfeit < 0 ||
        m->forfeit > DUEL_STATE_T_FORFEIT_BOTH) {
        snprintf(msg, msg_len, "outcome %d, forfeit %d: unknown", m->outcome, m->forfeit);
        return -1;
    }
    *w = ref;
    w->t = (uint32_t)m->step;
    w->food_mask = (uint32_t)m->food_mask;
    w->outcome = m->outcome;
    for (s = 0; s < 2; s++) {
        duel_robot *r = &w->robot[s];
        if (m->x[s] < rules->radius || m->x[s] > DUEL_FIX(DUEL_BOARD) - rules->radius || m->y[s] < rules->radius ||
            m->y[s] > DUEL_FIX(DUEL_BOARD) - rules->radius) {
            snprintf(msg, msg_len, "%s robot off the board", s == 0 ? "west" : "east");
            return -1;
        }
        if (m->eaten[s] < 0 || m->eaten[s] > DUEL_MAX_FOOD || ((uint32_t)m->eaten_by[s] & ~items) != 0) {
            snprintf(msg, msg_len, "%s robot's eaten count or items impossible", s == 0 ? "west" : "east");
            return -1;
        }
        r->x = m->x[s];
        r->y = m->y[s];
        r->heading = duel_lcm_angle_in(m->heading[s]);
        r->energy = m->energy[s];
        r->eaten = (uint8_t)m->eaten[s];
        ev->eaten_by[s] = (uint32_t)m->eaten_by[s];
    }
    ev->outcome = m->outcome;
    return 0;
}

const char *duel_lcm_outcome_text(int outcome, int forfeit)
{
    switch (forfeit) {
    case DUEL_STATE_T_FORFEIT_WEST: return "east wins (the west controller did not answer in time)";
    case DUEL_STATE_T_FORFEIT_EAST: return "west wins (the east controller did not answer in time)";
    case DUEL_STATE_T_FORFEIT_BOTH: return "draw (neither controller answered in time)";
    default: break;
    }
    return duel_outcome_text(outcome);
}

int duel_msg_decode_world(const void *data, size_t len, duel_rules *r, char *msg, size_t msg_len)
{
    /* fingerprint, version, identity, the rules: no strings, one size */
    const size_t size = 8u + 4u + 8u + DUEL_RULES_BYTES;
    duel_world_t m;
    size_t off = 0;
    int err = duel_msg_check(data, len, __duel_world_t_get_hash(), DUEL_WORLD_T_VERSION, "duel.world_t", msg, msg_len);
    if (err)
        return err;
    if (len != size) {
        snprintf(msg, msg_len, "a %zu-byte duel.world_t, not %zu", len, size);
        return DUEL_NODE_E_MALFORMED;
    }
    if (duel_world_t_decode(data, 0, (int)len, &m) != (int)len) {
        snprintf(msg, msg_len, "a %zu-byte duel.world_t that does not decode", len);
        return DUEL_NODE_E_MALFORMED;
    }
    if (duel_rules_decode(r, (const uint8_t *)m.rules, DUEL_RULES_BYTES, &off) != DUEL_OK) {
        snprintf(msg, msg_len, "duel.world_t: rules that cannot make a game (refused at byte %zu of them)", off);
        return DUEL_NODE_E_MALFORMED;
    }
    if ((uint64_t)m.identity != duel_rules_id(r)) {
        snprintf(msg, msg_len, "duel.world_t: identity %016llx, but its rules' is %016llx",
                 (unsigned long long)(uint64_t)m.identity, (unsigned long long)duel_rules_id(r));
        return DUEL_NODE_E_MALFORMED;
    }
    return DUEL_NODE_OK;
}
