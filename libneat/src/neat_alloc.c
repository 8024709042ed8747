/* neat_alloc.c - the single allocation hook every libneat allocation goes through. */
#include <stdlib.h>

#include "neat_internal.h"

void *neat_mem_realloc(const neat_alloc *a, void *ptr, size_t old_size, size_t new_size)
{
    if (a != NULL && a->fn != NULL)
        return a->fn(a->ud, ptr, old_size, new_size);
    if (new_size == 0) {
        free(ptr);
        return NULL;
    }
    return realloc(ptr, new_size);
}

void neat_mem_free(const neat_alloc *a, void *ptr, size_t size)
{
    if (ptr != NULL)
        (void)neat_mem_realloc(a, ptr, size, 0);
}

int neat_mem_reserve(const neat_alloc *a, void **arr, uint32_t *cap, uint32_t need, size_t elem)
{
    uint32_t ncap;
    void *p;
    if (need <= *cap)
        return NEAT_OK;
    ncap = *cap ? *cap : 8;
    while (ncap < need)
        ncap *= 2;
    p = neat_mem_realloc(a, *arr, (size_t)*cap * elem, (size_t)ncap * elem);
    if (p == NULL)
        return NEAT_E_NOMEM;
    *arr = p;
    *cap = ncap;
    return NEAT_OK;
}
