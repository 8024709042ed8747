/* duel_help.c - `duel_evolve COMMAND --help`: each command's synopsis and every option it takes, described. */
#include <string.h>

#include "duel_cli.h"
#include "duel_text.h"

typedef struct duel_help_entry {
    const char *command;
    const char *text;
} duel_help_entry;

/* The options here are the parsers' (tests/tools/duel_help.sh checks that
 * every option of the synopsis in `duel_evolve --help` is described). */
static const duel_help_entry duel_help_entries[] = {
    {"run",
     "usage: duel_evolve run --config FILE --out DIR [options]\n"
     "Competitive coevolution of two populations of robot-duel controllers (docs/tools.md).\n"
     "  --config FILE            the run's configuration (INI; configs/*.ini are the presets)\n"
     "  --out DIR                the run directory to create (checkpoint, champions/, CSVs, log.txt)\n"
     "  --set key=value          override one parameter (or section.key=value); repeatable\n"
     "  --seed S                 the seed (default: the configuration's)\n"
     "  --generations N          generations to run (default: the configuration's)\n"
     "  --threads T              threads playing the games (default 0: every core); the results do not\n"
     "                           depend on it\n"
     "  --quiet                  nothing on stderr but errors\n"
     "  --json                   one JSON object per generation on stdout (docs/tools.md, \"Progress\")\n"
     "  --record-champion-games  an LCM log of each generation champion's games (docs/lcm.md)\n"},
    {"resume",
     "usage: duel_evolve resume DIR [options]\n"
     "Continues a run from its last checkpoint: the same run as never stopping.\n"
     "  --generations N          run until N generations in all: more than config.ini's total extends\n"
     "                           the run (logged, stored in config.ini); fewer needs --shorten\n"
     "  --shorten                with --generations N below the run's total: shorten it for good\n"
     "  --set key=value          override one parameter from now on (logged; stored in config.ini's\n"
     "                           [overrides] with its generation, so that run --config RUN/config.ini\n"
     "                           plays the same run)\n"
     "  --threads T              threads playing the games (default 0: every core)\n"
     "  --quiet                  nothing on stderr but errors\n"
     "  --json                   one JSON object per generation on stdout\n"
     "  --record-champion-games  an LCM log of each generation champion's games\n"},
    {"config",
     "usage: duel_evolve config --dump [--config FILE] [--set key=value ...]\n"
     "Prints the whole configuration (every key, defaults filled in) as a run would use it.\n"
     "  --dump                   print it (the only action)\n"
     "  --config FILE            start from this INI file instead of the defaults\n"
     "  --set key=value          override one parameter; repeatable\n"},
    {"ladder",
     "usage: duel_evolve ladder DIR [--top | --levels L1-L2] [--against NAME,...] [--world NAME|FILE] [--csv FILE] "
     "[--force] [--json]\n"
     "Plays every dominant strategy of a run against each built-in strategy (idle, spinner, forager,\n"
     "hunter, forager-hunter) in 288-game comparisons, in the run's world, and writes DIR/ladder.csv and a\n"
     "table.\n"
     "  --top                    the highest dominant only (one row)\n"
     "  --levels L1-L2           dominance levels L1 to L2 only (or one level L)\n"
     "  --against NAME,...       these built-in strategies only, in this order\n"
     "  --csv FILE               the CSV to FILE (a part of the ladder, from --levels or --against, is\n"
     "                           written only there: DIR/ladder.csv keeps the whole ladder)\n"
     "  --world NAME|FILE        play in this world (a named one, or an INI file's [world]) instead of the\n"
     "                           run's; the ladder then goes only where --csv says\n"
     "  --json                   the results as one JSON object on stdout instead of the table\n"
     "  --force                  replace an existing output that is not recognisably this command's own (it is\n"
     "                           refused otherwise); an output that is one of the inputs is refused even then\n"},
    {"compare",
     "usage: duel_evolve compare RUN... --against RUN... [options]\n"
     "The paper's performance measure: each candidate run's highest dominant against every dominant of\n"
     "every ranking run (docs/tools.md, \"compare\").\n"
     "  --against RUN...         the ranking runs (after the candidates)\n"
     "  --threads T              threads playing the comparisons (default 0: every core)\n"
     "  --json FILE              the summary and every pair as JSON\n"
     "  --csv FILE               one row per (candidate, ranking) pair\n"
     "  --cache FILE             one cache of played comparisons (default: each candidate's\n"
     "                           compare-cache.csv)\n"
     "  --force                  replace an existing output that is not recognisably this command's own (it is\n"
     "                           refused otherwise); an output that is one of the inputs is refused even then\n"},
    {"experiment",
     "usage: duel_evolve experiment PLAN --out DIR [options]\n"
     "       duel_evolve experiment resume DIR [--jobs J] [--threads T] [--quiet]\n"
     "       duel_evolve experiment report DIR [--html [--games top|all|none] [--embed] [--force]]\n"
     "       duel_evolve experiment PLAN --dry-run\n"
     "The paper's section 6 from a plan: every method's runs, the performance measure, the ladders,\n"
     "Table 1 and the figures in DIR/report/ (docs/experiment.md).\n"
     "  --out DIR                the experiment directory to create\n"
     "  --set key=value          override a plan key; repeatable\n"
     "  --jobs J                 runs side by side (default 0: one per core)\n"
     "  --threads T              threads per run (default 0: cores / jobs)\n"
     "  --quiet                  nothing on stderr but errors\n"
     "  --dry-run                print what the plan would run, run nothing\n"
     "  resume DIR               continue an interrupted experiment\n"
     "  report DIR               write the report again from the files, playing nothing\n"
     "  --html                   (report) the report as web pages too, in DIR/report/html/: Table 1, the\n"
     "                           figures, a page per method with its runs' curves and ladders\n"
     "  --games top|all|none     (report --html) the games of each run's top level (default), of every\n"
     "                           level, or none, as duel pages in DIR/report/html/games/\n"
     "  --embed                  (report --html) the games inside the method pages\n"
     "  --force                  (report --html) replace a page that is not recognisably one of duel_evolve's\n"},
    {"play",
     "usage: duel_evolve play A B [--games 288 | --food K --side west|east] [--trace FILE.csv] "
     "[--lcm-log FILE.lcm] [--force] [--world NAME|FILE] [--json]\n"
     "One game (or a 288-game comparison) between A and B: champion blobs, genome files or\n"
     "builtin:NAME (idle, spinner, forager, hunter, forager-hunter).\n"
     "  --games 1|288            one game (default) or the comparison: every food configuration from\n"
     "                           both sides\n"
     "  --food K|training        the food configuration, 0..143, or the training layout (default)\n"
     "  --side west|east         A's side (default west)\n"
     "  --trace FILE.csv         every step's state, inputs and outputs (docs/duelsim.md)\n"
     "  --lcm-log FILE.lcm       the game as an LCM log (docs/lcm.md)\n"
     "  --world NAME|FILE        the world (a named one, or an INI file's [world]); default: the world of the\n"
     "                           runs the champions come from, else v1\n"
     "  --json                   the result as one JSON object on stdout (docs/tools.md, \"play --json\")\n"
     "  --force                  replace an existing output that is not recognisably this command's own (it is\n"
     "                           refused otherwise); an output that is one of the inputs is refused even then\n"},
    {"node",
     "usage: duel_evolve node controller BLOB --side west|east --lcm URL [--wait-ms N] [--timeout-ms N]\n"
     "       duel_evolve node world --food K|training --lcm URL [--timeout-ms N] [--wait-ms N] "
     "[--period-ms N] [--lcm-log FILE.lcm [--force]] [--world NAME|FILE]\n"
     "A game between processes over LCM (docs/lcm.md); URL is memq://, file:// or tcpq://HOST:PORT.\n"
     "  --side west|east         the controller's robot\n"
     "  --lcm URL                the LCM provider\n"
     "  --food K|training        the world's food configuration\n"
     "  --wait-ms N              how long to wait for the peers to start (default 30000)\n"
     "  --timeout-ms N           how long a silent peer is waited for (world 1000 per step,\n"
     "                           controller 10000)\n"
     "  --period-ms N            the world's pace, one step per N ms (default 0: as fast as it can)\n"
     "  --lcm-log FILE.lcm       the world records every message it publishes and accepts\n"
     "  --world NAME|FILE        the world node plays in this world (published first on DUEL_WORLD)\n"
     "  --force                  replace an existing output that is not recognisably this command's own (it is\n"
     "                           refused otherwise); an output that is one of the inputs is refused even then\n"},
    {"log",
     "usage: duel_evolve log info FILE.lcm\n"
     "       duel_evolve log dump FILE.lcm [--channel C]\n"
     "An LCM log of duels: its channels and games (info), or every message as text (dump).\n"
     "  --channel C              only the messages of channel C\n"},
    {"inspect",
     "usage: duel_evolve inspect BLOB | GENOME | RUN_DIR | CHECKPOINT\n"
     "A champion blob's or genome file's nodes and connections (a genome file's genes too), or what a\n"
     "run's checkpoint holds (docs/tools.md, \"inspect\"). No options.\n"},
    {"dot",
     "usage: duel_evolve dot BLOB|GENOME [-o FILE.dot [--force]] [--min-weight W]\n"
     "The network as Graphviz (dot -Tpng FILE.dot -o FILE.png): hidden nodes in rows by depth, dead\n"
     "ones grey dashed, a legend at the bottom (docs/tools.md, \"dot\").\n"
     "  -o FILE.dot              write to FILE.dot (atomically) instead of stdout\n"
     "  --min-weight W           leave out the connections whose |weight| is below W (0..8; default 0)\n"
     "  --force                  replace an existing output that is not recognisably this command's own (it is\n"
     "                           refused otherwise); an output that is one of the inputs is refused even then\n"},
    {"render",
     "usage: duel_evolve render (LOG.lcm | A B [--food K --side west|east --world NAME|FILE]) (--out DIR | --html FILE.html) [options]\n"
     "A duel's frames as PNG images (and a video), or as one self-contained web page, from an LCM log\n"
     "or from a game played now (docs/render.md).\n"
     "  --out DIR                the directory for frame-K.png\n"
     "  --html FILE.html         the game as a web page: the board, the sensors, the energies and each\n"
     "                           network's activations, step by step (opens from file:// in any browser)\n"
     "  --food K|training        the game's food configuration (A B only)\n"
     "  --side west|east         A's side (A B only)\n"
     "  --world NAME|FILE        the game's world (A B only; default: the runs' of the champions, else v1)\n"
     "  --size S                 S x S pixels, 64..2048 (default 600)\n"
     "  --every N                every Nth step's frame, and the last (default 1)\n"
     "  --sensors                draw the rangefinder sectors\n"
     "  --trails                 draw the path each robot's centre has taken so far\n"
     "  --video FILE.mp4         encode the frames with ffmpeg\n"
     "  --fps F                  the video's frames per second, 1..120 (default 30)\n"
     "  --force                  replace an existing output that is not recognisably this command's own (it is\n"
     "                           refused otherwise); an output that is one of the inputs is refused even then\n"},
    {"report",
     "usage: duel_evolve report RUN --html DIR [--games all|top|none] [--embed] [--force]\n"
     "A run's web pages (docs/render.md, \"Web pages\"): DIR/index.html with the run's curves and its dominance\n"
     "ladder (with the ladder's results when RUN/ladder.csv has them), and each level's games against the level\n"
     "below and every built-in strategy as duel pages in DIR/games/.\n"
     "  --html DIR               where the pages go (created; not a run's or an experiment's directory)\n"
     "  --games all|top|none     the games of every level (default), of the top level only, or none\n"
     "  --embed                  the games inside index.html instead of pages of their own\n"
     "  --force                  replace an existing page that is not recognisably one of duel_evolve's\n"},
    {"render-net",
     "usage: duel_evolve render-net BLOB|GENOME --out FILE.png [--force] [--min-weight W]\n"
     "The network drawn by Graphviz as a PNG, as the dot command draws it (docs/render.md).\n"
     "  --out FILE.png           the image to write (atomically)\n"
     "  --min-weight W           leave out the connections whose |weight| is below W (0..8; default 0)\n"
     "  --force                  replace an existing output that is not recognisably this command's own (it is\n"
     "                           refused otherwise); an output that is one of the inputs is refused even then\n"},
    {"export",
     "usage: duel_evolve export BLOB|GENOME --c-array NAME [-o FILE.c] [--header FILE.h] [--force]\n"
     "       duel_evolve export --world NAME|FILE (--c-array NAME [-o FILE.c] | --raw -o FILE) [--force]\n"
     "The champion as a C array for a firmware, or a world's rules as their canonical bytes\n"
     "(docs/firmware.md).\n"
     "  --c-array NAME           the array's name (a C identifier)\n"
     "  -o FILE.c                write to FILE.c (atomically) instead of stdout\n"
     "  --header FILE.h          also a header: the array, NAME_BLOB_SIZE, NAME_MEM_SIZE (the bytes nrt_load\n"
     "                           needs), NAME_INPUTS, NAME_OUTPUTS; the .c then includes it\n"
     "  --world NAME|FILE        export a world's rules (a named one, or an INI file's [world]) instead\n"
     "  --raw                    with --world: the bytes themselves to -o FILE (the host twin's WORLD.bin)\n"
     "  --force                  replace an existing output that is not recognisably this command's own (it is\n"
     "                           refused otherwise); an output that is one of the inputs is refused even then\n"},
};

int duel_help_wanted(int argc, char **argv)
{
    int i;
    for (i = 0; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0)
            return 1;
    return 0;
}

int duel_help(const char *command, FILE *f)
{
    size_t i;
    for (i = 0; i < sizeof duel_help_entries / sizeof duel_help_entries[0]; i++)
        if (strcmp(command, duel_help_entries[i].command) == 0) {
            fputs(duel_help_entries[i].text, f);
            return 0;
        }
    return -1;
}

int duel_cli_missing_value(const char *command, const char *opt, const char *const *takes_value)
{
    for (; *takes_value != NULL; takes_value++)
        if (strcmp(opt, *takes_value) == 0) {
            fprintf(stderr, "duel_evolve: %s: %s needs a value\n", command, opt);
            return 2;
        }
    fprintf(stderr, "duel_evolve: %s: unknown option '%s' (duel_evolve %s --help)\n", command, duel_esc(opt), command);
    return 2;
}
