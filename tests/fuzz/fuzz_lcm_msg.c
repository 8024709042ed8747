/* fuzz_lcm_msg.c - libFuzzer harness: any bytes as each duel LCM message, through the checked decoders and, over memq://, to a controller node and a world node as they receive them from the bus. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "duel_lcm.h"
#include "neat.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static lcm_t *fm_lcm;
static duel_node_ctrl fm_ctrl;
static duel_node_world fm_world;
static duel_node_world_opts fm_opts;
static duel_node_world_result fm_res;
static nrt_net fm_net;
static uint8_t fm_blob[4096];
static uint64_t fm_mem[2048]; /* aligned, as nrt_load asks */

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    neat_params p = neat_params_default();
    neat_pop *pop;
    size_t len;
    (void)argc;
    (void)argv;
    /* a controller to step: the minimal network of the duel */
    if (neat_pop_create(&pop, &p, NULL, 1, NULL) != NEAT_OK ||
        neat_blob_write(neat_pop_genome(pop, 0), p.n_inputs, p.n_outputs, fm_blob, sizeof fm_blob, &len) !=
            NEAT_OK ||
        nrt_load(&fm_net, fm_blob, len, fm_mem, sizeof fm_mem) != NRT_OK)
        abort();
    neat_pop_free(pop);
    fm_lcm = lcm_create("memq://");
    fm_opts.food_config = DUEL_TRAINING;
    fm_opts.timeout_ms = 1;
    fm_opts.wait_ms = 1;
    if (fm_lcm == NULL || duel_node_ctrl_start(&fm_ctrl, fm_lcm, &fm_net, 0, "fuzz") != 0 ||
        duel_node_world_open(&fm_world, fm_lcm, &fm_opts, &fm_res) != 0)
        abort();
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char *const channels[] = {DUEL_CH_STATE, DUEL_CH_SENSE_WEST, DUEL_CH_SENSE_EAST, DUEL_CH_MOTOR_WEST,
                                           DUEL_CH_MOTOR_EAST, DUEL_CH_NET};
    duel_sense_t s;
    duel_motor_t m;
    duel_state_t st;
    duel_net_t nt;
    char msg[400];
    int n = 0;
    if (size == 0)
        return 0;
    /* the decoders alone: a success leaves what a cleanup frees */
    if (duel_msg_decode_sense(data + 1, size - 1, &s, msg, sizeof msg) != DUEL_NODE_OK && msg[0] == '\0')
        __builtin_trap();
    if (duel_msg_decode_motor(data + 1, size - 1, &m, msg, sizeof msg) == DUEL_NODE_OK)
        duel_motor_t_decode_cleanup(&m);
    if (duel_msg_decode_state(data + 1, size - 1, &st, msg, sizeof msg) == DUEL_NODE_OK)
        duel_state_t_decode_cleanup(&st);
    if (duel_msg_decode_net(data + 1, size - 1, &nt, msg, sizeof msg) == DUEL_NODE_OK) {
        /* accepted only with a side and a step that exist */
        if ((nt.side != 0 && nt.side != 1) || nt.step < DUEL_NET_T_BUILTIN || nt.step > DUEL_NET_T_PROPAGATE)
            __builtin_trap();
        duel_net_t_decode_cleanup(&nt);
    }
    {
        /* the world message: accepted only with rules that make a game and their identity */
        duel_rules r;
        if (duel_msg_decode_world(data + 1, size - 1, &r, msg, sizeof msg) == DUEL_NODE_OK &&
            duel_rules_check(&r, NULL, NULL) != DUEL_OK)
            __builtin_trap();
    }
    /* as the nodes receive it: the first byte picks the channel; protocol errors are forgotten so that every
     * input reaches the handlers */
    fm_ctrl.err = 0;
    fm_world.err = 0;
    if (lcm_publish(fm_lcm, channels[data[0] % 6], data + 1, (unsigned)(size - 1)) != 0)
        abort();
    while (n++ < 16 && lcm_handle_timeout(fm_lcm, 0) > 0)
        ;
    return 0;
}
