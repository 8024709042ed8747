/* fw_figures.c - the firmware example's measurements on the target: RAM per champion, instructions per network step and per game step, stack used. */
#include "fw_duels.h"
#include "fw_port.h"

#ifndef FW_MACHINE_NAME
#define FW_MACHINE_NAME "?"
#endif

extern const uint8_t fw_champion_a[];
extern const size_t fw_champion_a_len;
extern const uint8_t fw_champion_b[];
extern const size_t fw_champion_b_len;
/* from the port's linker script */
extern uint8_t fw_bss_end[], fw_stack_top[];

int main(void);

#define FW_CAL_SPINS 1000000u /* calibration: 2,000,000 instructions */
#define FW_STEPS 1000u       /* nrt_step calls per network */
#define FW_STACK_PAINT 0xA5u

static void fw_write(void *ud, const char *s, size_t n)
{
    (void)ud;
    fw_port_write(s, n);
}

static uint32_t fw_elapsed(uint32_t since)
{
    return (fw_port_counter() - since) & fw_port_counter_mask;
}

/* Counter units for FW_PORT_SPIN_INSNS * spins instructions, the call's own
 * overhead cancelled by subtracting a run of half the length. */
static uint32_t fw_units_for_spins(uint32_t spins)
{
    uint32_t t0 = fw_port_counter(), full, half;
    fw_port_spin(2u * spins);
    full = fw_elapsed(t0);
    t0 = fw_port_counter();
    fw_port_spin(spins);
    half = fw_elapsed(t0);
    return full - half;
}

/* Instructions, in tenths, for `units` counter units. */
static uint32_t fw_tenths(uint32_t units, uint32_t cal_units, uint32_t per)
{
    uint64_t insns10 = (uint64_t)units * (10u * FW_PORT_SPIN_INSNS * FW_CAL_SPINS);
    uint64_t d = (uint64_t)cal_units * per;
    return (uint32_t)((insns10 + d / 2u) / d);
}

static void fw_line_tenths(fw_line *l, uint32_t t)
{
    fw_line_udec(l, t / 10u);
    fw_line_str(l, ".");
    fw_line_udec(l, t % 10u);
}

static const nrt_q15 *volatile fw_sink; /* keeps the baseline loop's calls */

/* Counter units for FW_STEPS calls of nrt_step (inputs already in place, so
 * nothing is copied, as in duel_play), minus the same loop without the step. */
static uint32_t fw_time_steps(nrt_net *net)
{
    uint32_t i, t0, with, without;
    nrt_q15 *in = nrt_inputs(net);
    for (i = 0; i < DUEL_N_INPUTS; i++)
        in[i] = (nrt_q15)(i == 0 ? NRT_ONE : (int32_t)(i * 2521u % 32768u) - 16384);
    nrt_step(net, in, NULL);
    /* the other activation buffer gets the same inputs; they stay put after */
    in = nrt_inputs(net);
    for (i = 0; i < DUEL_N_INPUTS; i++)
        in[i] = (nrt_q15)(i == 0 ? NRT_ONE : (int32_t)(i * 2521u % 32768u) - 16384);
    t0 = fw_port_counter();
    for (i = 0; i < FW_STEPS; i++)
        nrt_step(net, nrt_inputs(net), NULL);
    with = fw_elapsed(t0);
    t0 = fw_port_counter();
    for (i = 0; i < FW_STEPS; i++)
        fw_sink = nrt_inputs(net);
    without = fw_elapsed(t0);
    return with - without;
}

/* The champion's network as a propagate blob (docs/formats.md: version 2,
 * the step byte set, the CRC again) in buf, loaded into mem; the same
 * connections, so the two modes' figures compare. 0 or an nrt_error. */
static int fw_load_propagate(nrt_net *net, const uint8_t *blob, size_t len, uint8_t *buf, size_t cap, uint8_t *mem,
                             size_t mem_len, size_t *need)
{
    uint32_t crc;
    size_t k;
    int err;
    if (len > cap || len < NRT_HEADER_SIZE)
        return NRT_E_NOMEM;
    for (k = 0; k < len; k++)
        buf[k] = blob[k];
    buf[NRT_OFF_VERSION] = NRT_FORMAT_VERSION_PROPAGATE;
    buf[NRT_OFF_STEP] = NRT_STEP_PROPAGATE;
    crc = nrt_crc32(0, buf, NRT_OFF_CRC);
    crc = nrt_crc32(crc, buf + NRT_HEADER_SIZE, len - NRT_HEADER_SIZE);
    buf[NRT_OFF_CRC] = (uint8_t)crc;
    buf[NRT_OFF_CRC + 1] = (uint8_t)(crc >> 8);
    buf[NRT_OFF_CRC + 2] = (uint8_t)(crc >> 16);
    buf[NRT_OFF_CRC + 3] = (uint8_t)(crc >> 24);
    err = nrt_mem_required(buf, len, need);
    return err ? err : nrt_load(net, buf, len, mem, mem_len);
}

int main(void)
{
    static uint8_t arena[FW_ARENA];
    static uint8_t pblob[1024]; /* a propagate copy of a champion's blob (B: 840 bytes) */
    nrt_net pnet;
    const uint8_t *blob[2] = {fw_champion_a, fw_champion_b};
    const size_t len[2] = {fw_champion_a_len, fw_champion_b_len};
    nrt_net net[2];
    duel_controller ctrl[2];
    duel_result r;
    fw_line l;
    size_t used = 0, need;
    uint32_t cal, t0, units, i;
    uint8_t *p;
    uintptr_t sp_now = (uintptr_t)&l; /* about where this frame is */

    l.n = 0;
    fw_port_counter_start();
    cal = fw_units_for_spins(FW_CAL_SPINS);
    fw_line_str(&l, "figures on ");
    fw_line_str(&l, FW_MACHINE_NAME);
    fw_line_str(&l, ": counter calibrated with ");
    fw_line_udec(&l, FW_PORT_SPIN_INSNS * FW_CAL_SPINS);
    fw_line_str(&l, " instructions = ");
    fw_line_udec(&l, cal);
    fw_line_str(&l, " counter units");
    fw_line_end(&l, fw_write, NULL);
    {
        uint32_t c0, c1;
        fw_line_str(&l, "core cycle counter: ");
        if (fw_port_cycles(&c0) != 0) {
            fw_line_str(&l, "none on this core");
        } else {
            fw_port_spin(FW_CAL_SPINS);
            fw_port_cycles(&c1);
            fw_line_udec(&l, c1 - c0);
            fw_line_str(&l, " for ");
            fw_line_udec(&l, FW_PORT_SPIN_INSNS * FW_CAL_SPINS);
            fw_line_str(&l, " instructions");
            if (c1 == c0)
                fw_line_str(&l, " (it does not count in this machine model)");
        }
        fw_line_end(&l, fw_write, NULL);
    }
    if (cal == 0) {
        fw_line_str(&l, "the counter does not advance: run QEMU with -icount shift=0");
        fw_line_end(&l, fw_write, NULL);
        return FW_EXIT_FAILED;
    }

    for (i = 0; i < 2; i++) {
        int err = nrt_mem_required(blob[i], len[i], &need);
        if (!err)
            err = nrt_load(&net[i], blob[i], len[i], arena + used, sizeof arena - used);
        if (err) {
            fw_line_str(&l, "champion refused: ");
            fw_line_str(&l, fw_nrt_error_name(err));
            fw_line_end(&l, fw_write, NULL);
            return FW_EXIT_REFUSED;
        }
        used += need;
        units = fw_time_steps(&net[i]);
        fw_line_str(&l, i == 0 ? "champion A: " : "champion B: ");
        fw_line_udec(&l, net[i].n_conns);
        fw_line_str(&l, " connections, ");
        fw_line_udec(&l, net[i].n_nodes);
        fw_line_str(&l, " nodes; blob ");
        fw_line_udec(&l, (uint32_t)len[i]);
        fw_line_str(&l, " bytes + state ");
        fw_line_udec(&l, (uint32_t)need);
        fw_line_str(&l, " bytes = ");
        fw_line_udec(&l, (uint32_t)(len[i] + need));
        fw_line_str(&l, " bytes; nrt_step ");
        fw_line_tenths(&l, fw_tenths(units, cal, FW_STEPS));
        fw_line_str(&l, " instructions (");
        fw_line_tenths(&l, fw_tenths(units, cal, FW_STEPS * net[i].n_conns));
        fw_line_str(&l, " per connection)");
        fw_line_end(&l, fw_write, NULL);
        ctrl[i].net = &net[i];
        ctrl[i].builtin = 0;
        /* the same network stepped in propagate mode (docs/runtime.md) */
        err = fw_load_propagate(&pnet, blob[i], len[i], pblob, sizeof pblob, arena + used, sizeof arena - used, &need);
        if (err) {
            fw_line_str(&l, "propagate copy refused: ");
            fw_line_str(&l, fw_nrt_error_name(err));
            fw_line_end(&l, fw_write, NULL);
            return FW_EXIT_REFUSED;
        }
        units = fw_time_steps(&pnet);
        fw_line_str(&l, i == 0 ? "champion A, propagate: state " : "champion B, propagate: state ");
        fw_line_udec(&l, (uint32_t)need);
        fw_line_str(&l, " bytes; nrt_step ");
        fw_line_tenths(&l, fw_tenths(units, cal, FW_STEPS));
        fw_line_str(&l, " instructions (");
        fw_line_tenths(&l, fw_tenths(units, cal, FW_STEPS * pnet.n_conns));
        fw_line_str(&l, " per connection)");
        fw_line_end(&l, fw_write, NULL);
    }

    /* a whole game, B against A, with the stack painted below this frame to
     * find how deep the game goes */
    for (p = fw_bss_end; (uintptr_t)p < sp_now - 256u; p++)
        *p = FW_STACK_PAINT;
    t0 = fw_port_counter();
    if (duel_play(&ctrl[1], &ctrl[0], 77, &r, NULL, NULL) != DUEL_OK)
        return FW_EXIT_FAILED;
    units = fw_elapsed(t0);
    for (p = fw_bss_end; (uintptr_t)p < sp_now && *p == FW_STACK_PAINT; p++)
        ;
    fw_line_str(&l, "game B vs A, food 77: ");
    fw_line_udec(&l, r.steps);
    fw_line_str(&l, " steps, ");
    fw_line_tenths(&l, fw_tenths(units, cal, r.steps));
    fw_line_str(&l, " instructions per game step (sensing, both networks, motion, food)");
    fw_line_end(&l, fw_write, NULL);
    fw_line_str(&l, "stack: ");
    fw_line_udec(&l, (uint32_t)(fw_stack_top - p));
    fw_line_str(&l, " bytes used at most (from the top of RAM)");
    fw_line_end(&l, fw_write, NULL);
    return FW_EXIT_OK;
}
