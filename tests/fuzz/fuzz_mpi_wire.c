/* fuzz_mpi_wire.c - libFuzzer harness for the messages a rank of an MPI job decodes: a chunk of games with its blobs (duel_wire_work_take, then every blob it names loaded by the runtime), and a chunk's results (duel_wire_result_read). */
#include <assert.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "duel_mpi_wire.h"
#include "neat_phenotype.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The input is a 2-byte split point (little-endian; 0: none) and one or two WORK messages (a second chunk of the
 * same batch reuses the first one's networks); the same bytes are then read as a RESULT. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    duel_wire_store s;
    duel_rules rules;
    duel_match *m = NULL;
    size_t m_cap = 0, body = size > 2 ? size - 2 : 0, cut = size > 2 ? (size_t)data[0] | (size_t)data[1] << 8 : 0;
    size_t part;
    duel_result_hdr rh;
    memset(&s, 0, sizeof s);
    if (cut >= body)
        cut = 0;
    for (part = 0; part < 2 && body > 0; part++) {
        const uint8_t *p = data + 2 + (part == 0 ? 0 : cut);
        size_t len = part == 0 ? (cut ? cut : body) : body - cut;
        uint8_t *buf;
        duel_work_hdr h;
        if (part == 1 && cut == 0)
            break;
        buf = (uint8_t *)malloc(len);
        if (buf == NULL)
            break;
        memcpy(buf, p, len);
        if (duel_wire_work_take(&s, buf, len, &h, &rules, &m, &m_cap) != 0) {
            free(buf); /* refused: still the caller's */
            continue;
        }
        {
            /* what a rank does next: every network of every game loaded (the runtime checks the blob), a
               builtin (no blob: its number in len, duel_games.c) checked as a number */
            neat_phenotype ph;
            uint32_t i;
            neat_phenotype_init(&ph, NULL);
            assert(h.count > 0 && h.count <= len);
            for (i = 0; i < h.count; i++) {
                const duel_net *a = &s.nets[m[i].a], *b = &s.nets[m[i].b];
                assert(m[i].a < s.cap && m[i].b < s.cap);
                if (a->blob != NULL)
                    (void)neat_phenotype_load_blob(&ph, a->blob, a->len);
                if (b->blob != NULL)
                    (void)neat_phenotype_load_blob(&ph, b->blob, b->len);
            }
            neat_phenotype_free(&ph);
        }
    }
    if (body >= sizeof rh) {
        memcpy(&rh, data + 2, sizeof rh);
        if (duel_wire_result_read(data + 2, body, rh.batch, (size_t)rh.from, body - sizeof rh, &rh) == 0)
            assert(rh.count == body - sizeof rh && (rh.err == 0 || rh.err_at < rh.count));
    }
    duel_wire_store_free(&s);
    free(m);
    return 0;
}
