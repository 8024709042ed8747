/* duel_stats.c - mean, standard deviation, and the exact (small samples) or normal (large) Mann-Whitney U and Wilcoxon signed-rank tests. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "duel_stats.h"

double duel_stats_mean(const double *v, size_t n)
{
    double s = 0.0;
    size_t k;
    for (k = 0; k < n; k++)
        s += v[k];
    return n ? s / (double)n : 0.0;
}

double duel_stats_sd(const double *v, size_t n)
{
    double m = duel_stats_mean(v, n), s = 0.0;
    size_t k;
    if (n < 2)
        return 0.0;
    for (k = 0; k < n; k++)
        s += (v[k] - m) * (v[k] - m);
    return sqrt(s / (double)(n - 1));
}

typedef struct duel_ranked {
    double v;
    size_t at;
} duel_ranked;

static int duel_ranked_cmp(const void *a, const void *b)
{
    const duel_ranked *x = (const duel_ranked *)a, *y = (const duel_ranked *)b;
    if (x->v != y->v)
        return x->v < y->v ? -1 : 1;
    return x->at < y->at ? -1 : x->at > y->at;
}

/* Twice the mid-rank of each value (integers: ranks 1..n, a tie of k values
 * at ranks r..r+k-1 gets 2r+k-1 each) into rank2[at], and the sum of t^3 - t
 * over the ties into *ties. 0 or -1 (out of memory). */
static int duel_ranks2(const double *v, size_t n, uint32_t *rank2, double *ties)
{
    duel_ranked *s = (duel_ranked *)malloc((n ? n : 1) * sizeof *s);
    size_t i, j, k;
    if (s == NULL)
        return -1;
    for (i = 0; i < n; i++) {
        s[i].v = v[i];
        s[i].at = i;
    }
    qsort(s, n, sizeof *s, duel_ranked_cmp);
    *ties = 0.0;
    for (i = 0; i < n; i = j) {
        for (j = i + 1; j < n && s[j].v == s[i].v; j++)
            ;
        for (k = i; k < j; k++)
            rank2[s[k].at] = (uint32_t)(i + 1 + j); /* 2 * (i + 1 + j) / 2: ranks i+1 .. j */
        *ties += (double)(j - i) * (double)(j - i) * (double)(j - i) - (double)(j - i);
    }
    free(s);
    return 0;
}

/* P(|S - mean| >= |s_obs - mean|) from counts of S over 0..max (all in doubled units). */
static double duel_tail2(const double *count, size_t max, int64_t s_obs, int64_t mean2, double total)
{
    /* mean2 is twice the mean, so that every comparison stays in integers */
    int64_t dev = llabs(2 * s_obs - mean2);
    double hit = 0.0;
    size_t s;
    for (s = 0; s <= max; s++)
        if (count[s] != 0.0 && llabs(2 * (int64_t)s - mean2) >= dev)
            hit += count[s];
    hit /= total;
    return hit > 1.0 ? 1.0 : hit;
}

static double duel_normal_p(double z)
{
    return erfc(fabs(z) / sqrt(2.0));
}

int duel_stats_mwu(const double *x, size_t nx, const double *y, size_t ny, duel_test *t)
{
    size_t n = nx + ny, i, k;
    double *v, ties;
    uint32_t *r2;
    int64_t s_obs = 0;
    memset(t, 0, sizeof *t);
    t->p = 1.0;
    if (nx == 0 || ny == 0)
        return -1;
    v = (double *)malloc(n * sizeof *v);
    r2 = (uint32_t *)malloc(n * sizeof *r2);
    if (v == NULL || r2 == NULL || (memcpy(v, x, nx * sizeof *v), memcpy(v + nx, y, ny * sizeof *v),
                                    duel_ranks2(v, n, r2, &ties)) != 0) {
        free(v);
        free(r2);
        return -1;
    }
    for (i = 0; i < nx; i++)
        s_obs += r2[i];
    /* U = (rank sum of x) - nx (nx + 1) / 2, the rank sum being s_obs / 2 */
    t->statistic = (double)s_obs / 2.0 - (double)nx * (double)(nx + 1) / 2.0;
    if (n <= DUEL_STATS_EXACT_MAX) {
        /* count[j][s]: the ways to choose j of the values seen so far with doubled rank sum s */
        size_t max = n * (n + 1), j;
        double *count = (double *)calloc((nx + 1) * (max + 1), sizeof *count), total = 0.0;
        if (count == NULL) {
            free(v);
            free(r2);
            return -1;
        }
        count[0] = 1.0;
        for (k = 0; k < n; k++)
            for (j = (k + 1 < nx ? k + 1 : nx); j >= 1; j--) {
                double *to = count + j * (max + 1), *from = count + (j - 1) * (max + 1);
                size_t s;
                for (s = max; s >= r2[k]; s--)
                    to[s] += from[s - r2[k]];
            }
        for (k = 0; k <= max; k++)
            total += count[nx * (max + 1) + k];
        t->p = duel_tail2(count + nx * (max + 1), max, s_obs, 2 * (int64_t)(nx * (n + 1)), total);
        t->exact = 1;
        free(count);
    } else {
        double mu = (double)nx * (double)ny / 2.0, var, dev;
        var = (double)nx * (double)ny / 12.0 * ((double)(n + 1) - ties / ((double)n * (double)(n - 1)));
        dev = fabs(t->statistic - mu) - 0.5;
        t->p = var > 0.0 ? duel_normal_p((dev > 0.0 ? dev : 0.0) / sqrt(var)) : 1.0;
    }
    free(v);
    free(r2);
    return 0;
}

int duel_stats_wilcoxon(const double *d, size_t n, duel_test *t)
{
    double *a, ties;
    uint32_t *r2;
    size_t m = 0, i;
    int64_t s_obs = 0, total2 = 0;
    memset(t, 0, sizeof *t);
    t->p = 1.0;
    a = (double *)malloc((n ? n : 1) * sizeof *a);
    r2 = (uint32_t *)malloc((n ? n : 1) * sizeof *r2);
    if (a == NULL || r2 == NULL) {
        free(a);
        free(r2);
        return -1;
    }
    for (i = 0; i < n; i++)
        if (d[i] != 0.0)
            a[m++] = fabs(d[i]);
    t->n = m;
    if (m == 0 || duel_ranks2(a, m, r2, &ties) != 0) {
        free(a);
        free(r2);
        return m == 0 ? 0 : -1;
    }
    for (i = 0, m = 0; i < n; i++)
        if (d[i] != 0.0) {
            if (d[i] > 0.0)
                s_obs += r2[m];
            total2 += r2[m++];
        }
    t->statistic = (double)s_obs / 2.0;
    if (m <= DUEL_STATS_EXACT_MAX) {
        /* count[s]: the sign patterns whose positive doubled ranks sum to s */
        size_t max = (size_t)total2, k, s;
        double *count = (double *)calloc(max + 1, sizeof *count);
        if (count == NULL) {
            free(a);
            free(r2);
            return -1;
        }
        count[0] = 1.0;
        for (k = 0; k < m; k++)
            for (s = max; s >= r2[k]; s--)
                count[s] += count[s - r2[k]];
        t->p = duel_tail2(count, max, s_obs, total2, ldexp(1.0, (int)m));
        t->exact = 1;
        free(count);
    } else {
        double mu = (double)m * (double)(m + 1) / 4.0, var, dev;
        var = (double)m * (double)(m + 1) * (double)(2 * m + 1) / 24.0 - ties / 48.0;
        dev = fabs(t->statistic - mu) - 0.5;
        t->p = var > 0.0 ? duel_normal_p((dev > 0.0 ? dev : 0.0) / sqrt(var)) : 1.0;
    }
    free(a);
    free(r2);
    return 0;
}
