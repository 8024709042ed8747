"""neat_stats.py - the statistics the registered comparisons use (docs/neat-cpp.md, docs/study2.md), in plain
Python so that they run anywhere the project does: Mann-Whitney (exact for small samples, normal with the tie
correction otherwise), Fisher's exact test, Holm's correction, a seeded permutation test, and the power of a
Mann-Whitney test by simulation. Every test is two-sided."""
import itertools
import math
import random


def u_stat(a, b):
    """Mann-Whitney U of a against b: pairs where a wins, ties counting half."""
    return sum(1.0 if x > y else 0.5 if x == y else 0.0 for x in a for y in b)


def ranks(values):
    """Mid-ranks (1-based; ties share the mean of their ranks)."""
    order = sorted(range(len(values)), key=lambda i: values[i])
    ranks = [0.0] * len(values)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            ranks[order[k]] = (i + j) / 2.0 + 1.0
        i = j + 1
    return ranks


def mann_whitney(a, b):
    """Two-sided p of the Mann-Whitney test of a against b: exact (every split of the pooled values) when there are
    at most 50,000 splits (5 against 5: 252; 9 against 9: 48,620), else the normal approximation with the tie
    correction and a continuity correction of 1/2. Returns (U, p); p is 1.0 when either sample is empty."""
    n1, n2 = len(a), len(b)
    if n1 == 0 or n2 == 0:
        return float("nan"), 1.0
    u = u_stat(a, b)
    mean = n1 * n2 / 2.0
    if math.comb(n1 + n2, n1) <= 50000:
        pooled = list(a) + list(b)
        obs = abs(u - mean)
        hits = total = 0
        for idx in itertools.combinations(range(n1 + n2), n1):
            chosen = set(idx)
            ga = [pooled[i] for i in idx]
            gb = [pooled[i] for i in range(n1 + n2) if i not in chosen]
            total += 1
            hits += abs(u_stat(ga, gb) - mean) >= obs - 1e-9
        return u, hits / total
    rk = ranks(list(a) + list(b))
    n = n1 + n2
    ties = {}
    for r in rk:
        ties[r] = ties.get(r, 0) + 1
    tie_term = sum(t ** 3 - t for t in ties.values()) / (n * (n - 1))
    var = n1 * n2 / 12.0 * ((n + 1) - tie_term)
    if var <= 0:
        return u, 1.0
    z = (abs(u - mean) - 0.5) / math.sqrt(var)
    if z < 0:
        z = 0.0
    return u, math.erfc(z / math.sqrt(2.0))


def _log_choose(n, k):
    return math.lgamma(n + 1) - math.lgamma(k + 1) - math.lgamma(n - k + 1)


def fisher_exact(a_yes, a_no, b_yes, b_no):
    """Two-sided p of Fisher's exact test on the 2 x 2 table [[a_yes, a_no], [b_yes, b_no]]: the probability, under
    the margins, of every table at most as likely as the observed one."""
    n1, n2 = a_yes + a_no, b_yes + b_no
    k = a_yes + b_yes
    n = n1 + n2

    def prob(x):
        return math.exp(_log_choose(n1, x) + _log_choose(n2, k - x) - _log_choose(n, k))

    obs = prob(a_yes)
    lo, hi = max(0, k - n2), min(k, n1)
    return min(1.0, sum(prob(x) for x in range(lo, hi + 1) if prob(x) <= obs * (1 + 1e-7)))


def holm(pvalues):
    """Holm's step-down adjustment: the adjusted p-values, in the order given."""
    m = len(pvalues)
    order = sorted(range(m), key=lambda i: pvalues[i])
    adjusted = [0.0] * m
    running = 0.0
    for rank, i in enumerate(order):
        running = max(running, min(1.0, (m - rank) * pvalues[i]))
        adjusted[i] = running
    return adjusted


def permutation_p(a, b, statistic, rounds=20000, seed=1):
    """Two-sided p of a permutation test: the share of random relabellings of the pooled values (a seeded
    generator) whose |statistic| is at least the observed |statistic(a, b)|, as (hits + 1) / (rounds + 1).
    statistic must be 0 in expectation under the null (e.g. a difference of means)."""
    rng = random.Random(seed)
    obs = abs(statistic(a, b))
    pooled = list(a) + list(b)
    hits = 0
    for _ in range(rounds):
        rng.shuffle(pooled)
        if abs(statistic(pooled[:len(a)], pooled[len(a):])) >= obs - 1e-12:
            hits += 1
    return (hits + 1) / (rounds + 1)


def mw_power(sample_a, sample_b, n, alpha, rounds=2000, seed=1):
    """The power of a two-sided Mann-Whitney test of n against n at level alpha when the two methods' values are
    distributed as sample_a and sample_b (resampled with replacement): the share of simulated studies with p <
    alpha."""
    rng = random.Random(seed)
    hits = 0
    for _ in range(rounds):
        a = [rng.choice(sample_a) for _ in range(n)]
        b = [rng.choice(sample_b) for _ in range(n)]
        if mann_whitney(a, b)[1] < alpha:
            hits += 1
    return hits / rounds


def mean(xs):
    return sum(xs) / len(xs) if xs else float("nan")


def median(xs):
    s = sorted(xs)
    if not s:
        return float("nan")
    m = len(s) // 2
    return s[m] if len(s) % 2 else (s[m - 1] + s[m]) / 2.0
