"""test_neat_stats.py - scripts/neat_stats.py against values known from tables and by hand."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "scripts"))
import neat_stats as st  # noqa: E402


def close(a, b, tol):
    assert abs(a - b) <= tol, (a, b)


def main():
    # exact Mann-Whitney: the smallest two-sided p of 5 against 5 is 2/252, of 4 against 4 2/70, of 3 against 3 0.1
    close(st.mann_whitney([6, 7, 8, 9, 10], [1, 2, 3, 4, 5])[1], 2 / 252, 1e-12)
    close(st.mann_whitney([5, 6, 7, 8], [1, 2, 3, 4])[1], 2 / 70, 1e-12)
    close(st.mann_whitney([4, 5, 6], [1, 2, 3])[1], 0.1, 1e-12)
    assert st.mann_whitney([1, 2, 3], [1, 2, 3])[1] == 1.0
    # the normal approximation for 30 against 30 shifted by one sd-ish: close to the textbook z
    a = list(range(30))
    b = [x + 10.5 for x in range(30)]
    u, p = st.mann_whitney(a, b)
    z = (abs(u - 450) - 0.5) / math.sqrt(30 * 30 * 61 / 12.0)
    close(p, math.erfc(z / math.sqrt(2)), 1e-12)
    assert p < 0.01
    # Fisher: [[3, 1], [1, 3]] two-sided 0.4857; [[10, 0], [0, 10]] 2 / C(20, 10)
    close(st.fisher_exact(3, 1, 1, 3), 0.485714, 1e-5)
    close(st.fisher_exact(10, 0, 0, 10), 2 / 184756, 1e-12)
    close(st.fisher_exact(5, 5, 5, 5), 1.0, 1e-9)
    # Holm: 0.01, 0.04, 0.03 -> 0.03, 0.06, 0.06
    adj = st.holm([0.01, 0.04, 0.03])
    close(adj[0], 0.03, 1e-12)
    close(adj[1], 0.06, 1e-12)
    close(adj[2], 0.06, 1e-12)
    # the permutation test finds a clear difference and not an absent one
    diff = lambda x, y: st.mean(x) - st.mean(y)  # noqa: E731
    assert st.permutation_p([5, 6, 7, 8, 9, 10], [0, 1, 2, 3, 4, 5], diff, rounds=2000) < 0.01
    assert st.permutation_p([1, 2, 3, 4], [1, 2, 3, 4], diff, rounds=500) == 1.0
    # power: identical distributions reject at about alpha; far apart ones always
    assert st.mw_power(list(range(10)), list(range(10)), 30, 0.05, rounds=300) < 0.12
    assert st.mw_power(list(range(10)), list(range(100, 110)), 5, 0.05, rounds=50) == 1.0
    print("ok: neat_stats")


if __name__ == "__main__":
    main()
