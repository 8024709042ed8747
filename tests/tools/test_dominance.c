/* test_dominance.c - dominance.csv rows of any length written and read back with their scores, generations.csv read back, and malformed files refused with their line. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "duel_dominance.h"
#include "duel_generations.h"

/* A dominance.csv of n levels, level k beating the k - 1 below it. */
static char *td_file(uint32_t n, size_t *len)
{
    size_t cap = 1 << 16, used;
    uint32_t k, j;
    char *text = (char *)malloc(cap);
    uint16_t *w = (uint16_t *)malloc((n + 1) * sizeof *w), *l = (uint16_t *)malloc((n + 1) * sizeof *l);
    assert_non_null(text);
    strcpy(text, DUEL_DOMINANCE_HEADER);
    used = strlen(text);
    for (k = 1; k <= n; k++) {
        char *row;
        size_t rl;
        for (j = 0; j + 1 < k; j++) {
            w[j] = (uint16_t)(200 + j % 88);
            l[j] = (uint16_t)(j % 100);
        }
        row = duel_dominance_row_text(k, 3 * k, k % 2 ? 'A' : 'B', k % 7, 39 + k, k - 1, w, l);
        assert_non_null(row);
        rl = strlen(row);
        while (used + rl + 1 > cap) {
            cap *= 2;
            text = (char *)realloc(text, cap);
            assert_non_null(text);
        }
        memcpy(text + used, row, rl + 1);
        used += rl;
        free(row);
    }
    free(w);
    free(l);
    *len = used;
    return text;
}

/* 1,000 levels: the top row holds 999 scores (about 7 KB; the writer once cut rows at 2,000 characters) */
static void test_long_rows(void **state)
{
    size_t len;
    char *text = td_file(1000, &len), err[300];
    duel_dominance_row *rows;
    uint32_t n;
    (void)state;
    {
        const char *last = text + len - 1; /* the final newline */
        while (last > text && last[-1] != '\n')
            last--;
        assert_true(text + len - last > 6000);
    }
    assert_int_equal(duel_dominance_parse("d.csv", text, len, &rows, &n, err, sizeof err), 0);
    assert_int_equal(n, 1000);
    assert_int_equal(rows[999].level, 1000);
    assert_int_equal(rows[999].generation, 3000);
    assert_string_equal(rows[999].pop, "B");
    assert_int_equal(rows[999].conns, 1039);
    free(rows);
    /* a torn last row (the writer died, a cut copy) is refused, never dropped: it may be the top level */
    assert_int_equal(duel_dominance_parse("d.csv", text, len - 5, &rows, &n, err, sizeof err), -1);
    assert_string_equal(err, "d.csv:1001: the last row is cut short (no newline): resuming the run rebuilds the "
                             "file from its checkpoint (duel_evolve resume RUN)");
    assert_null(rows);
    free(text);
}

static void td_bad(const char *text, const char *want)
{
    duel_dominance_row *rows = (duel_dominance_row *)1;
    uint32_t n = 7;
    char err[300];
    assert_int_equal(duel_dominance_parse("d.csv", text, strlen(text), &rows, &n, err, sizeof err), -1);
    if (strstr(err, want) == NULL)
        fail_msg("'%s': got '%s', expected '%s'", text, err, want);
    assert_null(rows);
    assert_int_equal(n, 0);
}

static void test_refused(void **state)
{
    (void)state;
    td_bad("", "d.csv:1: not a dominance.csv");
    td_bad("level,generation\n", "d.csv:1: not a dominance.csv");
    td_bad(DUEL_DOMINANCE_HEADER "1,0,A,0,39,\n2,5,C,0,39,3:1\n", "d.csv:3: not a dominance row");
    td_bad(DUEL_DOMINANCE_HEADER "1,0,A,0,39,\n2,5,B,0,39,\n", "d.csv:3: level 2 needs 1 w:l scores");
    td_bad(DUEL_DOMINANCE_HEADER "1,0,A,0,39,\n2,5,B,0,39,3:1 4:4\n", "d.csv:3: level 2 needs 1");
    td_bad(DUEL_DOMINANCE_HEADER "1,0,A,0,39,\n3,5,B,0,39,3:1 4:4\n", "d.csv:3: level 3 of generation 5 out of order");
    /* named for what they are (issue 49): a duplicated row, a CRLF copy */
    td_bad(DUEL_DOMINANCE_HEADER "1,0,A,0,39,\n2,5,B,0,39,3:1\n2,5,B,0,39,3:1\n", "d.csv:4: the row before again (a duplicated row)");
    td_bad("level,generation,population,hidden,connections,wins\r\n1,0,A,0,39,\r\n", "d.csv:1: a CRLF line end");
    td_bad(DUEL_DOMINANCE_HEADER "1,4,A,0,39,\n2,4,B,0,39,3:1\n", "d.csv:3: level 2 of generation 4 out of order");
    td_bad(DUEL_DOMINANCE_HEADER "1,99999999999,A,0,39,\n", "d.csv:2: not a dominance row");
    td_bad(DUEL_DOMINANCE_HEADER "1,-1,A,0,39,\n", "d.csv:2: not a dominance row");
    td_bad(DUEL_DOMINANCE_HEADER "1,0,A,0,39\n", "d.csv:2: not a dominance row");
    td_bad(DUEL_DOMINANCE_HEADER "0,0,A,0,39,\n", "d.csv:2: level 0");
}

/* The scores: level k's k - 1 results, against level k - 1 first. */
static void test_scores(void **state)
{
    const char *text = DUEL_DOMINANCE_HEADER "1,0,A,0,39,\n2,3,B,0,40,150:100\n3,9,A,1,44,200:50 170:90\n";
    duel_dominance_row *rows;
    duel_dominance_score *sc;
    uint32_t n;
    char err[200];
    (void)state;
    assert_int_equal(duel_dominance_parse_scores("d.csv", text, strlen(text), &rows, &n, &sc, err, sizeof err), 0);
    assert_int_equal(n, 3);
    assert_int_equal(rows[1].scores, 0);
    assert_int_equal(rows[2].scores, 1);
    assert_int_equal(sc[0].wins, 150);
    assert_int_equal(sc[0].losses, 100);
    assert_int_equal(sc[1].wins, 200); /* level 3 against level 2 */
    assert_int_equal(sc[2].losses, 90); /* level 3 against level 1 */
    free(rows);
    free(sc);
}

static void test_generations(void **state)
{
    const char *text = DUEL_GENERATIONS_HEADER "0,A,2,0.7812,1,3.0000,0.0000,39.0000,0,39,0,0,39,39,1536,1,1.149\n"
                                               "0,B,6,0.2188,1,3.0000,0.0000,39.0000,0,39,0,2,39,45,1536,0,1.149\n"
                                               "1,A,3,0.5,1,3.0,0.0,39.0,0,39,0,1,39,41,1536,0,0.5\n"
                                               "1,B,3,0.5,1,3.0,0.0,39.0,0,39,0,1,39,4"; /* torn */
    const char *gap = DUEL_GENERATIONS_HEADER "0,A,2,0.7812,1,3.0000,0.0000,39.0000,0,39,0,0,39,39,1536,1,1.149\n"
                                              "0,B,6,0.2188,1,3.0000,0.0000,39.0000,0,39,0,2,39,45,1536,0,1.149\n"
                                              "1,B,3,0.5,1,3.0,0.0,39.0,0,39,0,1,39,41,1536,0,0.5\n";
    duel_gen_row *rows;
    size_t n;
    char err[200];
    (void)state;
    /* a torn last row is refused, never dropped silently */
    assert_int_equal(duel_generations_parse("g.csv", text, strlen(text), &rows, &n, err, sizeof err), -1);
    assert_string_equal(err, "g.csv:5: the last row is cut short (no newline): resuming the run cuts it");
    assert_null(rows);
    /* a row missing in the middle */
    assert_int_equal(duel_generations_parse("g.csv", gap, strlen(gap), &rows, &n, err, sizeof err), -1);
    assert_string_equal(err, "g.csv:4: generation 1 B follows generation 0 B: rows are missing");
    assert_int_equal(duel_generations_parse("g.csv", gap, strlen(gap) - 51, &rows, &n, err, sizeof err), 0);
    assert_int_equal((int)n, 2);
    free(rows);
    assert_int_equal(duel_generations_parse("g.csv", text, (size_t)(strrchr(text, '\n') - text) + 1, &rows, &n, err,
                                            sizeof err), 0);
    assert_int_equal((int)n, 3);
    assert_int_equal(rows[1].pop, 'B');
    assert_int_equal(rows[1].max_hidden, 2);
    assert_int_equal(rows[1].max_conns, 45);
    assert_float_equal(rows[2].seconds, 0.5, 1e-12);
    assert_float_equal(rows[0].games, 1536.0, 0.0);
    assert_int_equal(duel_generations_done(rows, n), 1); /* generation 1 has no B row yet */
    free(rows);
    assert_int_equal(duel_generations_parse("g.csv", "gen\n", 4, &rows, &n, err, sizeof err), -1);
    assert_string_equal(err, "g.csv:1: not a generations.csv (expected its header)");
    text = DUEL_GENERATIONS_HEADER "0,C,2,0.7,1,3.0,0.0,39.0,0,39,0,0,39,39,1536,1,1.1\n";
    assert_int_equal(duel_generations_parse("g.csv", text, strlen(text), &rows, &n, err, sizeof err), -1);
    assert_string_equal(err, "g.csv:2: not a row of 17 fields with population A or B");
    text = DUEL_GENERATIONS_HEADER "0,A,2,0.7,1,3.0,0.0,39.0,0,39,0,x,39,39,1536,1,1.1\n";
    assert_int_equal(duel_generations_parse("g.csv", text, strlen(text), &rows, &n, err, sizeof err), -1);
    assert_string_equal(err, "g.csv:2: field 12 is not a number");
    assert_null(rows);
    /* named for what they are (issue 49), with their own code: a duplicated row, a CRLF copy */
    text = DUEL_GENERATIONS_HEADER "0,A,2,0.7,1,3.0,0.0,39.0,0,39,0,0,39,39,1536,1,1.1\n"
                                   "0,A,2,0.7,1,3.0,0.0,39.0,0,39,0,0,39,39,1536,1,1.1\n";
    assert_int_equal(duel_generations_parse("g.csv", text, strlen(text), &rows, &n, err, sizeof err), -3);
    assert_string_equal(err, "g.csv:3: the row before again (a duplicated row): delete one of the two");
    text = "generation,population\r\n0,A\r\n";
    assert_int_equal(duel_generations_parse("g.csv", text, strlen(text), &rows, &n, err, sizeof err), -3);
    assert_non_null(strstr(err, "g.csv:1: a CRLF line end"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_long_rows),
        cmocka_unit_test(test_refused),
        cmocka_unit_test(test_scores),
        cmocka_unit_test(test_generations),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
