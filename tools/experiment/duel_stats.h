/* duel_stats.h - the statistics of an experiment's tables: mean and standard deviation, the two-sided Mann-Whitney U test and the Wilcoxon signed-rank test, exact for small samples. */
#ifndef DUEL_STATS_H
#define DUEL_STATS_H

#include <stddef.h>

/* Samples up to this size (both together for Mann-Whitney) get the exact
 * distribution, ties included; larger ones the normal approximation with
 * tie and continuity corrections. */
#define DUEL_STATS_EXACT_MAX 64

typedef struct duel_test {
    double statistic; /* Mann-Whitney: U of the first sample; Wilcoxon: W+, the sum of the positive ranks */
    double p;         /* two-sided; 1.0 when there is nothing to test */
    int exact;        /* 1: from the exact distribution */
    size_t n;         /* Wilcoxon: the nonzero differences used */
} duel_test;

double duel_stats_mean(const double *v, size_t n);
/* The sample standard deviation (n - 1); 0 for fewer than two values. */
double duel_stats_sd(const double *v, size_t n);

/* Two-sided Mann-Whitney U test of x against y: the probability, when both
 * come from one distribution, of a rank sum of x at least as far from its
 * mean as the one observed. Ties get mid-ranks; the exact distribution is
 * the one of those mid-ranks (a permutation test). 0, or -1 when out of
 * memory or a sample is empty. */
int duel_stats_mwu(const double *x, size_t nx, const double *y, size_t ny, duel_test *t);

/* Two-sided Wilcoxon signed-rank test of the paired differences d (zero
 * differences dropped, mid-ranks for ties). 0, or -1 when out of memory. */
int duel_stats_wilcoxon(const double *d, size_t n, duel_test *t);

#endif /* DUEL_STATS_H */
