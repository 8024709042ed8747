#!/usr/bin/env bash
# html_cli.sh - duel_evolve's web pages from the outside: render --html (same bytes twice, with frames, from an LCM log), report RUN --html (pages, games, --games, --embed, again over its own pages), experiment report --html, and the refusals.
set -euo pipefail
duel=$1
bench=$2
fixture=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bench" --write-blobs "$tmp" > /dev/null
cd "$tmp"

fail() { echo "FAIL: $*" >&2; exit 1; }
# expect_refusal STATUS PATTERN ARGS...: the command exits STATUS and says PATTERN on stderr
expect_refusal() {
  local want=$1 pattern=$2 rc=0
  shift 2
  "$duel" "$@" > out.txt 2> err.txt || rc=$?
  [ "$rc" -eq "$want" ] || fail "$* exited $rc, not $want: $(cat err.txt)"
  grep -q -- "$pattern" err.txt || fail "$*: no '$pattern' in: $(cat err.txt)"
}

# a game's page: one line on stdout, the same bytes twice, the same page beside frames
"$duel" render net39a.blob builtin:forager --food 3 --html a.html > a.txt
grep -q "^page: a.html ([0-9]* bytes, [0-9]* frames)$" a.txt || fail "render --html said: $(cat a.txt)"
"$duel" render net39a.blob builtin:forager --food 3 --html b.html > /dev/null
cmp a.html b.html
"$duel" render net39a.blob builtin:forager --food 3 --out frames --every 100 --html c.html > c.txt
cmp a.html c.html
grep -q "frames of 600x600" c.txt || fail "frames and a page: $(cat c.txt)"
grep -q "^page: c.html" c.txt || fail "frames and a page: no page line"
# a networks' game: each side's network and its hidden activations
"$duel" render net202a.blob net202b.blob --html n.html > /dev/null
grep -q '"hidden":20' n.html || fail "n.html has no network of 20 hidden nodes"
# from an LCM log: the board as played, no network (a log holds none)
"$duel" play net39a.blob builtin:forager --food 3 --lcm-log g.lcm > /dev/null
"$duel" render g.lcm --html log.html > /dev/null
grep -q '"step":"sync","net":null' log.html || fail "a log's page names a network"

# refusals: nothing replaced
echo keep > other.html
expect_refusal 2 "is not a web page of duel_evolve" render net39a.blob builtin:forager --html other.html
[ "$(cat other.html)" = keep ] || fail "a refused --html was replaced"
"$duel" render net39a.blob builtin:forager --html other.html --force > /dev/null
head -c 15 other.html | grep -q "<!DOCTYPE html>" || fail "--force did not replace"
expect_refusal 2 "needs --out DIR" render net39a.blob builtin:forager --html x.html --video v.mp4
expect_refusal 2 "one of" render net39a.blob builtin:forager --html net39a.blob
expect_refusal 2 "cannot write" render net39a.blob builtin:forager --html nodir/x.html
[ ! -e x.html ] || fail "a refused render wrote x.html"

# a run's pages
cp -r "$fixture/runs/complexify-3" run
levels=$(($(wc -l < run/dominance.csv) - 1))
"$duel" report run --html pages > r.txt
grep -q "^$((6 * levels)) pages in pages (games in games/)$" r.txt || fail "report said: $(cat r.txt)"
[ "$(ls pages/games | wc -l)" -eq $((6 * levels - 1)) ] || fail "$(ls pages/games | wc -l) game pages for $levels levels"
for f in pages/games/*.html; do
  grep -q "$(basename "$f")" pages/index.html || fail "index.html does not link $f"
done
cp -r pages pages1
"$duel" report run --html pages > /dev/null # its own pages: replaced, the same bytes
diff -r pages pages1 > /dev/null || fail "report twice gave other pages"
"$duel" report run --html top --games top > /dev/null
[ "$(ls top/games | wc -l)" -eq 6 ] || fail "--games top wrote $(ls top/games | wc -l) game pages"
"$duel" report run --html none --games none > /dev/null
[ "$(ls none)" = index.html ] || fail "--games none wrote $(ls none)"
"$duel" report run --html emb --embed > /dev/null
[ "$(ls emb)" = index.html ] || fail "--embed wrote $(ls emb)"
[ "$(grep -o '"embed":[0-9]*' emb/index.html | wc -l)" -eq $((6 * levels - 1)) ] || fail "--embed: wrong game count"
echo keep > pages/games/level-01-vs-idle.html
expect_refusal 2 "is not a web page of duel_evolve" report run --html pages
[ "$(cat pages/games/level-01-vs-idle.html)" = keep ] || fail "a refused report replaced a file"
"$duel" report run --html pages --force > /dev/null
expect_refusal 2 "is a run or experiment directory" report run --html run
expect_refusal 2 "not a run directory" report pages --html p2
expect_refusal 2 "usage: duel_evolve report" report run
expect_refusal 2 "--games takes all, top or none" report run --html p3 --games some
[ ! -e p2 ] && [ ! -e p3 ] || fail "a refused report left a directory"

# an experiment's pages (the committed tiny experiment, reported again here)
cp -r "$fixture" exp
"$duel" experiment report exp --html > e.txt 2> /dev/null
grep -q "pages in exp/report/html (games in games/)" e.txt || fail "experiment report --html said: $(cat e.txt)"
for m in $(tail -n +2 exp/report/table1.csv | cut -d, -f1); do
  [ -f "exp/report/html/method-$m.html" ] || fail "no page for method $m"
  grep -q "\"method-$m.html\"" exp/report/html/index.html || fail "the index does not link method-$m.html"
done
# a method called "index" has its own page beside the index (its page was once replaced by the index, written last)
cp -r "$fixture" idx
sed -i 's/^\[method simplify\]/[method index]/' idx/plan.ini
mv idx/configs/simplify.ini idx/configs/index.ini && mv idx/runs/simplify-1 idx/runs/index-1
"$duel" experiment report idx --html --games none > /dev/null 2>&1 || fail "experiment report --html with a method index failed"
grep -q '"label":"simplify"' idx/report/html/method-index.html && fail "method-index.html is not the page of method index"
grep -q '"method":"index"' idx/report/html/method-index.html || fail "no page for the method called index"
grep -q '"method":null' idx/report/html/index.html || fail "index.html is not the experiment's index"
expect_refusal 2 "not an experiment directory" experiment report run --html
echo "html_cli: all checks passed"
