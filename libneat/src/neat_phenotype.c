/* neat_phenotype.c - genome -> blob -> runtime: what evolution evaluates is exactly what would be flashed. */
#include <math.h>
#include <string.h>

#include "neat_internal.h"
#include "neat_phenotype.h"

void neat_phenotype_init(neat_phenotype *ph, const neat_alloc *a)
{
    memset(ph, 0, sizeof *ph);
    if (a != NULL)
        ph->alloc = *a;
}

void neat_phenotype_free(neat_phenotype *ph)
{
    neat_alloc a = ph->alloc;
    neat_mem_free(&a, ph->blob, ph->blob_cap);
    neat_mem_free(&a, ph->mem, ph->mem_cap);
    neat_phenotype_init(ph, &a);
}

/* ph->blob holds ph->blob_len bytes: the network it describes, loaded. */
static int neat_phenotype_load_own(neat_phenotype *ph)
{
    size_t mem_need;
    int err = nrt_mem_required(ph->blob, ph->blob_len, &mem_need);
    if (err)
        return err - 100;
    if (mem_need > ph->mem_cap) {
        void *nm = neat_mem_realloc(&ph->alloc, ph->mem, ph->mem_cap, mem_need);
        if (nm == NULL)
            return NEAT_E_NOMEM;
        ph->mem = nm;
        ph->mem_cap = mem_need;
    }
    err = nrt_load(&ph->net, ph->blob, ph->blob_len, ph->mem, ph->mem_cap);
    return err ? err - 100 : 0;
}

static int neat_phenotype_reserve(neat_phenotype *ph, size_t need)
{
    if (need > ph->blob_cap) {
        uint8_t *nb = (uint8_t *)neat_mem_realloc(&ph->alloc, ph->blob, ph->blob_cap, need);
        if (nb == NULL)
            return NEAT_E_NOMEM;
        ph->blob = nb;
        ph->blob_cap = need;
    }
    return 0;
}

int neat_phenotype_load(neat_phenotype *ph, const neat_genome *g, const neat_params *p)
{
    int err = neat_phenotype_reserve(ph, neat_blob_size(g));
    if (err)
        return err;
    err = neat_blob_write_step(g, p->n_inputs, p->n_outputs, p->net_step, ph->blob, ph->blob_cap, &ph->blob_len);
    if (err)
        return err;
    return neat_phenotype_load_own(ph);
}

int neat_phenotype_load_blob(neat_phenotype *ph, const uint8_t *blob, size_t len)
{
    int err;
    if (blob == NULL && len > 0) /* no bytes to copy, whatever the length says */
        return NRT_E_ARG - 100;
    err = neat_phenotype_reserve(ph, len > 0 ? len : 1);
    if (err)
        return err;
    if (len > 0) /* an empty blob (NULL allowed) is refused by the loader, never copied from */
        memcpy(ph->blob, blob, len);
    ph->blob_len = len;
    return neat_phenotype_load_own(ph);
}

nrt_q15 neat_q15(double x)
{
    /* floor(y) saturated to [-32768, 32767], without the libm call (every
     * input of every network step comes through here): for y in range, a
     * conversion truncates toward zero, one less below zero gives the floor */
    double y = x * 32768.0 + 0.5;
    int32_t t;
    if (y >= 32768.0)
        return 32767;
    if (y < -32768.0)
        return -32768;
    if (y != y)
        return 0; /* NaN: before the conversion, which C leaves undefined for it */
    t = (int32_t)y;
    if ((double)t > y)
        t--;
    return (nrt_q15)t;
}

double neat_from_q15(nrt_q15 q)
{
    return (double)q / 32768.0;
}
