/* duel_trace.c - the per-step CSV trace of a game (columns in docs/duelsim.md), printed from fixed point with 6 decimals. */
#include "duel_trace.h"

static const char *const duel_side_names[2] = {"west", "east"};

void duel_trace_header(FILE *f)
{
    int s, i;
    fprintf(f, "t");
    for (s = 0; s < 2; s++) {
        fprintf(f, ",%s_x,%s_y,%s_heading,%s_energy", duel_side_names[s], duel_side_names[s], duel_side_names[s],
                duel_side_names[s]);
        for (i = 0; i < DUEL_N_INPUTS; i++)
            fprintf(f, ",%s_in%d", duel_side_names[s], i);
        for (i = 0; i < DUEL_N_OUTPUTS; i++)
            fprintf(f, ",%s_out%d", duel_side_names[s], i);
    }
    fprintf(f, ",food_mask,event,world_id,west_step,east_step\n");
}

int duel_trace_step_of(const duel_controller *c)
{
    if (c->net == NULL)
        return DUEL_TRACE_STEP_BUILTIN;
    return c->net->step == NRT_STEP_PROPAGATE ? DUEL_TRACE_STEP_PROPAGATE : DUEL_TRACE_STEP_SYNC;
}

const char *duel_trace_step_name(int step)
{
    switch (step) {
    case DUEL_TRACE_STEP_BUILTIN: return "builtin";
    case DUEL_TRACE_STEP_SYNC: return "sync";
    case DUEL_TRACE_STEP_PROPAGATE: return "propagate";
    default: return "unknown";
    }
}

/* heading in radians in (-pi, pi] */
static double duel_heading_rad(duel_angle a)
{
    const double pi = 3.14159265358979323846;
    if (a == DUEL_HALF_TURN)
        return pi;
    return (double)(int32_t)a * (pi / 2147483648.0);
}

void duel_trace_row(void *ud, const duel_world *w, const nrt_q15 in[2][DUEL_N_INPUTS],
                    const nrt_q15 out[2][DUEL_N_OUTPUTS], const duel_event *ev)
{
    const duel_trace *tr = (const duel_trace *)ud;
    FILE *f = tr->f;
    int s, i, first = 1;
    fprintf(f, "%u", (unsigned)w->t);
    for (s = 0; s < 2; s++) {
        const duel_robot *r = &w->robot[s];
        fprintf(f, ",%.6f,%.6f,%.6f,%.6f", r->x / 65536.0, r->y / 65536.0, duel_heading_rad(r->heading),
                r->energy / 65536.0);
        for (i = 0; i < DUEL_N_INPUTS; i++)
            fprintf(f, ",%.6f", in[s][i] / 32768.0);
        for (i = 0; i < DUEL_N_OUTPUTS; i++)
            fprintf(f, ",%.6f", out[s][i] / 32768.0);
    }
    fprintf(f, ",%u,", (unsigned)w->food_mask);
    /* events of this step, ';'-separated when several happen at once */
    for (s = 0; s < 2; s++)
        for (i = 0; i < DUEL_MAX_FOOD; i++)
            if (ev->eaten_by[s] & (1u << i)) {
                fprintf(f, "%seat:%s:%d", first ? "" : ";", duel_side_names[s], i);
                first = 0;
            }
    switch (ev->outcome) {
    case DUEL_WEST_WINS: fprintf(f, "%scollision:west", first ? "" : ";"); break;
    case DUEL_EAST_WINS: fprintf(f, "%scollision:east", first ? "" : ";"); break;
    case DUEL_DRAW: fprintf(f, "%scollision:draw", first ? "" : ";"); break;
    case DUEL_TIMEOUT: fprintf(f, "%stimeout", first ? "" : ";"); break;
    default: break;
    }
    fprintf(f, ",%016llx,%s,%s\n", (unsigned long long)tr->world_id, duel_trace_step_name(tr->step[0]),
            duel_trace_step_name(tr->step[1]));
}
