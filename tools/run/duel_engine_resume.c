/* duel_engine_resume.c - a run directory opened again: config.ini, the checkpoint and the records checked against each other (a hand edit refused, naming the key), lost records rebuilt, the resume's overrides scheduled. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "duel.h"
#include "duel_ctrl.h"
#include "duel_engine_internal.h"
#include "duel_files.h"
#include "duel_plan.h"
#include "duel_runtag.h"
#include "duel_text.h"
#include "duel_world_cfg.h"
#include "neat_coev.h"

/* A resume that did not open: its status, the engine given back. */
static int duel_resume_refused(duel_engine *R, int status)
{
    de_engine_discard(R);
    return status;
}

/* The checkpoint of a coevolution: 0; 1 when it does not exist; -1 after one line naming the file and the offset. */
static int duel_resume_ckpt(duel_engine *R, const char *path, neat_coev **out)
{
    char err[4600];
    int r = duel_ckpt_load_msg("", path, out, err, sizeof err);
    if (r < 0)
        de_err(R, "%s", de_esc_msg(R, err));
    return r;
}

/* The overrides a tag records from before generation g against config.ini's: the same lines, in the same order
 * (a change to one the run has played is a hand edit; those from g on are still to come). 1 when they agree. */
static int duel_tag_overrides_agree(const duel_config *cfg, const uint8_t *tag, size_t len, uint32_t g)
{
    size_t at = duel_run_tag_overrides(tag, len);
    uint32_t n = 0, k, j = 0;
    if (at < len) {
        at += 4;
        if (at + 4 > len)
            return 0;
        n = (uint32_t)tag[at] | (uint32_t)tag[at + 1] << 8 | (uint32_t)tag[at + 2] << 16 | (uint32_t)tag[at + 3] << 24;
        at += 4;
    }
    for (k = 0; k < n; k++) {
        uint32_t from, tl;
        if (at + 8 > len)
            return 0;
        from = (uint32_t)tag[at] | (uint32_t)tag[at + 1] << 8 | (uint32_t)tag[at + 2] << 16 |
               (uint32_t)tag[at + 3] << 24;
        tl = (uint32_t)tag[at + 4] | (uint32_t)tag[at + 5] << 8 | (uint32_t)tag[at + 6] << 16 |
             (uint32_t)tag[at + 7] << 24;
        at += 8;
        if (tl > len - at)
            return 0;
        if (from < g) {
            if (j >= cfg->n_over || cfg->over[j].from != from || strlen(cfg->over[j].sets) != tl ||
                memcmp(cfg->over[j].sets, tag + at, tl) != 0)
                return 0;
            j++;
        }
        at += tl;
    }
    /* config.ini has no line before g that the checkpoint lacks */
    return j == cfg->n_over || cfg->over[j].from >= g;
}

static int duel_check_tag(duel_engine *R, const uint8_t *tag, size_t len, const char *path, uint32_t g)
{
    uint8_t want[DUEL_TAG_MAX];
    size_t wlen;
    duel_rules made;
    char a[40], b[40];
    if (de_run_tag_of(R, want, &wlen) != 0)
        return -1;
    if (duel_tag_world(tag, len, &made, NULL) < 0) { /* an empty tag: world v1 */
        de_err(R, "%s: its world's rules (the game tag) are damaged\n", de_esc(R, path));
        return -1;
    }
    if (!duel_rules_equal(&made, &R->cfg.world)) {
        de_err(R, "%s: the run was made in world %s, but config.ini's [world] says %s: a run's "
                        "rules cannot change (restore config.ini, or start a new run)\n", de_esc(R, path),
                duel_world_label(&made, a, sizeof a), duel_world_label(&R->cfg.world, b, sizeof b));
        return -1;
    }
    if (len > 0 && !duel_tag_overrides_agree(&R->cfg, tag, len, g)) {
        de_err(R, "%s: the run was played with other [overrides] before generation %u than "
                        "config.ini says (a hand edit): restore config.ini\n", de_esc(R, path), g);
        return -1;
    }
    /* what makes the games, the overrides apart (compared above) */
    len = duel_run_tag_overrides(tag, len);
    wlen = duel_run_tag_overrides(want, wlen);
    if (len == 0 ? R->cfg.train_layouts != DUEL_TRAIN_FIXED || R->cfg.opp.n != 0
                 : len != wlen || memcmp(tag, want, len) != 0) {
        de_err(R, "%s: the run was made with other games than config.ini now makes ([run] "
                        "train_layouts, [opponents], their files in opponents/, or net_step changed): restore them, "
                        "or start a new run\n", de_esc(R, path));
        return -1;
    }
    return 0;
}

/* config.ini's start topology is the one the checkpoint carries. A blob or
 * genome file that is no longer there is not needed: the checkpoint has its network. */
static int duel_check_start(duel_engine *R, const char *ckpt)
{
    char err[DUEL_START_MAX_PATH + 200], st[DUEL_START_MAX_PATH + 16];
    const neat_genome *have = neat_coev_start(R->coev);
    neat_genome want;
    int same;
    if ((R->cfg.start.kind == DUEL_START_BLOB || R->cfg.start.kind == DUEL_START_GENOME) &&
        access(R->cfg.start.path, F_OK) != 0)
        return 0;
    if (duel_start_genome(&R->cfg, &want, err, sizeof err) != 0) {
        de_err(R, "%s\n", de_esc_msg(R, err));
        return -1;
    }
    same = duel_same_topology(have, &want);
    neat_genome_free(&want, NULL);
    if (!same) {
        duel_start_text(&R->cfg.start, st, sizeof st);
        de_err(R, "%s: started from %u hidden nodes and %u connections, but config.ini says "
                        "start = %s\n", ckpt, neat_genome_hidden_count(have), neat_genome_enabled_count(have), st);
        return -1;
    }
    return 0;
}

/* The population checkpoint of a run against fixed opponents: 0; 1 when it
 * does not exist; -1 after one line naming the file and the offset. */
static int duel_pop_ckpt_load(duel_engine *R, const char *path, neat_pop **out)
{
    char msg[4600];
    int r = duel_any_ckpt_load_msg("", path, NULL, out, NULL, msg, sizeof msg);
    if (r == -2)
        de_err(R, "%s: a coevolution's checkpoint, but config.ini names [opponents]: restore the run's config.ini",
               de_esc(R, path));
    else if (r < 0)
        de_err(R, "%s", de_esc_msg(R, msg));
    return r < 0 ? -1 : r;
}

/* 1 when one of the overrides sets [run] key (KEY=... or run.KEY=...). */
static int duel_sets_key(const char *const *sets, uint32_t n, const char *key)
{
    uint32_t k;
    size_t n_key = strlen(key);
    for (k = 0; k < n; k++) {
        const char *v = strncmp(sets[k], "run.", 4) == 0 ? sets[k] + 4 : sets[k];
        if (strncmp(v, key, n_key) == 0 && v[n_key] == '=')
            return 1;
    }
    return 0;
}

/* config.ini against what the checkpoint's run was made with: the NEAT
 * and coevolution parameters it holds (cp NULL for a run against fixed
 * opponents). A hand edit is never taken silently: a change is made with
 * --set, which is applied and logged. 0, or 2 after one line naming the
 * first key that differs. */
static int duel_check_edits(duel_engine *R, const duel_config *config_ini, const neat_params *np,
                            const neat_coev_params *cp, const char *dir, const char *const *sets, uint32_t n_sets, char *differs, size_t differs_cap)
{
    duel_config file = *config_ini, ck = *config_ini;
    char *a = NULL, *b = NULL, err[600], la[300], lb[300];
    size_t alen = 0, blen = 0;
    FILE *fa, *fb;
    int r = 0;
    ck.neat = *np;
    if (cp != NULL)
        ck.coev = *cp;
    /* a key this resume sets is a change made the right way, on both sides */
    if (duel_config_set_list(&file, sets, n_sets, NULL, err, sizeof err) != 0 ||
        duel_config_set_list(&ck, sets, n_sets, NULL, err, sizeof err) != 0)
        return 2; /* not reached: the same overrides were applied before */
    fa = open_memstream(&a, &alen);
    fb = open_memstream(&b, &blen);
    if (fa == NULL || fb == NULL) {
        if (fa != NULL)
            fclose(fa);
        if (fb != NULL)
            fclose(fb);
        free(a);
        free(b);
        de_err(R, "resume: out of memory\n");
        return 1;
    }
    duel_config_dump(fa, &file);
    duel_config_dump(fb, &ck);
    if (fclose(fa) != 0 || fclose(fb) != 0) {
        de_err(R, "resume: out of memory\n");
        r = 1;
    } else if (duel_plan_diff(a, b, la, lb, sizeof la) != 0) {
        if (differs != NULL) {
            /* config.ini as a run wrote it: an override of a resume that played no generation (or whose
             * checkpoint was not saved); the caller takes the checkpoint's */
            snprintf(differs, differs_cap, "config.ini said '%s', the checkpoint '%s'", la, lb);
            r = 3;
        } else {
            de_err(R, "%s/config.ini says '%s' but the run in its checkpoint has '%s': a hand edit "
                            "of config.ini is not taken (give a change as --set KEY=VALUE, which is applied and "
                            "logged, or restore config.ini)\n", de_esc(R, dir), la, lb);
            r = 2;
        }
    }
    free(a);
    free(b);
    return r;
}

/* config.ini as a run wrote it, but with parameters the checkpoint's run never played (a resume's --set whose
 * generation was never saved): the checkpoint is the run; config.ini follows it (written again once this resume's
 * own overrides are applied), and the log says so. 0, or 2 after one line. */
static int duel_take_checkpoint(duel_engine *R, duel_config *before, const neat_params *np, const neat_coev_params *cp,
                                const char *const *sets, uint32_t n_sets, const char *differs)
{
    char err[600];
    before->neat = *np;
    if (cp != NULL)
        before->coev = *cp;
    R->cfg.neat = *np;
    if (cp != NULL)
        R->cfg.coev = *cp;
    if (duel_config_set_list(&R->cfg, sets, n_sets, NULL, err, sizeof err) != 0) {
        de_err(R, "--set: %s\n", de_esc_msg(R, err)); /* not reached: the same overrides were applied before */
        return 2;
    }
    de_log(R, "resume: %s, an override of a resume that played no generation: the run is the checkpoint's, and "
                "config.ini is written again", differs);
    return 0;
}

/* A resume's parameters against its checkpoint at generation g: config.ini as played up to g - 1 (generation
 * 0's with the [overrides] before g) must be what the checkpoint holds; a sealed config.ini that is not (an
 * override of a resume from before [overrides], baked into [neat], whose generation was never saved) gives way
 * to the checkpoint. 0, or the exit status after one line. */
static int duel_resume_params(duel_engine *R, duel_config *before, const neat_params *np, const neat_coev_params *cp,
                              uint32_t g, int sealed, const char *const *psets, uint32_t n_psets, char *differs,
                              size_t differs_cap)
{
    duel_config played;
    char err[600];
    int e;
    if (duel_config_at(before, g > 0 ? g - 1u : 0, &played, err, sizeof err) != 0) {
        de_err(R, "%s/config.ini: %s\n", de_esc(R, R->dir), de_esc_msg(R, err));
        return 2;
    }
    /* a key this resume sets is a change made the right way, edited by hand to the same value or not */
    e = duel_check_edits(R, &played, np, cp, R->dir, psets, n_psets,
                         sealed == 1 && before->n_over == 0 ? differs : NULL, differs_cap);
    if (e == 3)
        return duel_take_checkpoint(R, before, np, cp, NULL, 0, differs);
    if (e != 0 || n_psets == 0)
        return e;
    {
        char quiet[700]; /* the probe says nothing: 3 when config.ini was edited to what --set gives */
        if (duel_check_edits(R, &played, np, cp, R->dir, NULL, 0, quiet, sizeof quiet) == 0)
            return 0;
    }
    /* config.ini edited by hand to what --set gives: the change applies from g (it goes into [overrides]), and
     * generation 0's values are the checkpoint's, the run having no overrides before */
    if (before->n_over > 0)
        return duel_check_edits(R, &played, np, cp, R->dir, NULL, 0, NULL, 0); /* says which key; with a schedule,
                                                                                * the hand edit stays refused */
    R->cfg.neat = *np;
    if (cp != NULL)
        R->cfg.coev = *cp;
    return 0;
}

/* This resume's parameter overrides go into [overrides] from generation g, and the run plays g with every
 * override up to it. 0, or 2 after one line. */
static int duel_resume_schedule(duel_engine *R, uint32_t g, const char *const *psets, uint32_t n_psets)
{
    char err[600];
    if (n_psets > 0 && g < R->cfg.generations &&
        duel_config_add_override(&R->cfg, g, psets, n_psets, err, sizeof err) != 0) {
        de_err(R, "resume: --set: %s\n", de_esc_msg(R, err));
        return 2;
    }
    if (duel_config_at(&R->cfg, g, &R->eff, err, sizeof err) != 0 || duel_config_check(&R->eff, err, sizeof err) != 0) {
        de_err(R, "%s\n", de_esc_msg(R, err));
        return 2;
    }
    R->first_applied = g + 1u;
    return 0;
}

int duel_engine_resume(duel_engine **out, const char *dir, const duel_engine_options *o)
{
    duel_engine *R;
    neat_pop *pop = NULL;
    char err[600], path[4200], differs[700] = "";
    const char *const *sets = o != NULL ? o->sets : NULL;
    const char *psets[64];
    uint32_t n_sets = o != NULL ? o->n_sets : 0, n_psets = 0, k, g;
    uint32_t gens = o != NULL ? o->generations : 0;
    int have_gens = gens > 0, shorten = o != NULL && o->shorten, c, e, sealed;
    uint32_t seal_gens = 0, seal_every = 0;
    duel_config before;

    *out = NULL;
    if ((e = de_engine_alloc(&R, dir, o)) != 0)
        return e;
    if (n_sets > 64) {
        de_err(R, "resume: at most 64 overrides at once");
        return duel_resume_refused(R, 2);
    }
    de_path(path, sizeof path, R->dir, "games");
    if (R->record_games && duel_mkdir(path) != 0) {
        de_err(R, "%s: cannot create: %s\n", de_esc(R, path), strerror(errno));
        return duel_resume_refused(R, 2);
    }
    duel_config_default(&R->cfg);
    de_path(path, sizeof path, R->dir, "config.ini");
    if (duel_config_load(&R->cfg, path, err, sizeof err) != 0) {
        de_err(R, "%s\n", de_esc_msg(R, err));
        return duel_resume_refused(R, 2);
    }
    before = R->cfg;
    if (R->cfg.reproduction != DUEL_REPRODUCE_LIBNEAT) {
        /* libneat would go on where NEAT C++ 1.2.1 reproduced, whose populations no file holds */
        de_err(R, "%s: [run] reproduction = neat-cpp-1.2.1: a run reproduced by NEAT C++ 1.2.1's own "
                        "code cannot be resumed (the release's populations are in no file); start it again (it is "
                        "deterministic: the same seed gives the same run)\n", de_esc(R, path));
        return duel_resume_refused(R, 2);
    }
    if (de_take_lock(R, R->dir) != 0)
        return duel_resume_refused(R, 2);
    /* the parameters (a [neat] or [coevolution] key) apply from the next generation on and go into [overrides];
     * the other keys ([run]'s) change config.ini itself. Both are checked here, on a copy, first. */
    {
        duel_config scratch = R->cfg;
        if (duel_config_set_list(&scratch, sets, n_sets, &k, err, sizeof err) != 0) {
            char esc[1100];
            de_err(R, "--set %s: %s\n", duel_text_escape(sets[k], esc, sizeof esc), de_esc_msg(R, err));
            return duel_resume_refused(R, 2);
        }
        for (k = 0; k < n_sets; k++) {
            if (duel_config_set_is_param(sets[k]))
                psets[n_psets++] = sets[k];
            else if (duel_config_set(&R->cfg, sets[k], err, sizeof err) != 0)
                return duel_resume_refused(R, 2); /* not reached: applied above */
        }
    }
    if (have_gens)
        R->cfg.generations = gens;
    /* the run's total changes only when asked: fewer generations than config.ini's needs --shorten */
    if (R->cfg.generations < before.generations && !shorten) {
        de_err(R, "resume: the run has %u generations in all (config.ini); %u would shorten it "
                        "for good: add --shorten to mean that\n", before.generations, R->cfg.generations);
        return duel_resume_refused(R, 2);
    }
    if (shorten && R->cfg.generations >= before.generations) {
        de_err(R, "resume: --shorten with %u generations, not fewer than the run's %u\n",
                R->cfg.generations, before.generations);
        return duel_resume_refused(R, 2);
    }
    if (R->cfg.seed != before.seed) {
        de_err(R, "--set seed: a run's seed cannot change; start a new run instead\n");
        return duel_resume_refused(R, 2);
    }
    if (memcmp(&R->cfg.start, &before.start, sizeof before.start) != 0) {
        de_err(R, "--set start: a run's start topology cannot change; start a new run instead\n");
        return duel_resume_refused(R, 2);
    }
    if (!duel_rules_equal(&R->cfg.world, &before.world)) {
        de_err(R, "--set: a run's [world] rules cannot change; start a new run instead\n");
        return duel_resume_refused(R, 2);
    }
    if (memcmp(&R->cfg.opp, &before.opp, sizeof before.opp) != 0) {
        de_err(R, "--set: a run's [opponents] cannot change; start a new run instead\n");
        return duel_resume_refused(R, 2);
    }
    if (R->cfg.train_layouts != before.train_layouts) {
        de_err(R, "--set train_layouts: a run's training food cannot change; start a new run "
                        "instead\n");
        return duel_resume_refused(R, 2);
    }
    {
        /* what the run would play with the overrides (wherever they are scheduled) */
        duel_config scratch;
        if (duel_config_check(&R->cfg, err, sizeof err) != 0 ||
            duel_config_at(&R->cfg, UINT32_MAX, &scratch, err, sizeof err) != 0 ||
            duel_config_set_list(&scratch, psets, n_psets, NULL, err, sizeof err) != 0 ||
            duel_config_check(&scratch, err, sizeof err) != 0) {
            de_err(R, "%s\n", de_esc_msg(R, err));
            return duel_resume_refused(R, 2);
        }
        if (scratch.neat.pop_size != R->cfg.neat.pop_size) {
            de_err(R, "the overrides do not fit this run (pop_size cannot change)\n");
            return duel_resume_refused(R, 2);
        }
        if (scratch.neat.net_step != R->cfg.neat.net_step) {
            /* its champions, dominants and strength rows are blobs of that step, checked against the checkpoint
             * in it */
            de_err(R, "--set net_step: a run's network step cannot change; start a new run "
                            "instead\n");
            return duel_resume_refused(R, 2);
        }
    }

    /* a hand edit of any key is refused: the NEAT and coevolution keys are named below (against the checkpoint),
     * the others ([run]'s generations, strength_every, ...) by the seal the run wrote */
    sealed = de_config_sealed(R->dir, &seal_gens, &seal_every);
    de_path(path, sizeof path, R->dir, "checkpoint.bin");
    c = R->cfg.opp.n > 0 ? duel_pop_ckpt_load(R, path, &pop) : duel_resume_ckpt(R, path, &R->coev);
    if (c < 0)
        return duel_resume_refused(R, 2);
    if (R->cfg.opp.n > 0 && (e = de_load_opponents(R, 1)) != 0) {
        neat_pop_free(pop);
        return duel_resume_refused(R, e);
    }
    if (c > 0) {
        /* died before its first checkpoint: start from generation 0; but a run that recorded
         * generations and lost its checkpoint cannot go on */
        if (de_has_history(R->dir, err, sizeof err)) {
            de_err(R, "%s: missing, but the run directory holds %s: cannot resume without it "
                            "(restore it from a backup, or start a new run)\n", de_esc(R, path), de_esc_msg(R, err));
            return duel_resume_refused(R, 2);
        }
        de_free_run(R);
        /* no generation was played: the parameters are generation 0's */
        if (duel_config_set_list(&R->cfg, psets, n_psets, NULL, err, sizeof err) != 0)
            return duel_resume_refused(R, 2); /* not reached: checked above */
        if ((e = de_create(R)) != 0)
            return duel_resume_refused(R, e);
    } else if (R->cfg.opp.n > 0) {
        size_t tlen = 0;
        const uint8_t *tag = neat_pop_game(pop, &tlen);
        g = neat_pop_generation(pop);
        e = duel_resume_params(R, &before, neat_pop_params(pop), NULL, g, sealed, psets, n_psets, differs,
                               sizeof differs);
        if (e == 0 && duel_check_tag(R, tag, tlen, path, g) != 0)
            e = 2;
        if (e == 0)
            e = duel_resume_schedule(R, g, psets, n_psets);
        if (e != 0) {
            neat_pop_free(pop);
            return duel_resume_refused(R, e);
        }
        e = neat_pop_set_params(pop, &R->eff.neat);
        if (e == 0)
            e = duel_fixed_new(&R->fixed, pop, &R->eff, R->opp, R->cfg.opp.n);
        else
            neat_pop_free(pop);
        if (e) {
            de_err(R, "the overrides do not fit this run (pop_size cannot change): %s\n",
                    neat_strerror(e));
            return duel_resume_refused(R, 2);
        }
    } else {
        size_t tlen = 0;
        const uint8_t *tag = neat_coev_game(R->coev, &tlen);
        if (neat_coev_seed(R->coev) != R->cfg.seed) {
            de_err(R, "%s: seed %llu, but config.ini says %u\n", de_esc(R, path),
                    (unsigned long long)neat_coev_seed(R->coev), R->cfg.seed);
            return duel_resume_refused(R, 2);
        }
        g = neat_coev_generation(R->coev);
        e = duel_resume_params(R, &before, neat_pop_params(neat_coev_pop(R->coev, 0)), neat_coev_get_params(R->coev),
                               g, sealed, psets, n_psets, differs, sizeof differs);
        if (e == 0 && (duel_check_start(R, path) != 0 || duel_check_tag(R, tag, tlen, path, g) != 0))
            e = 2;
        if (e == 0)
            e = duel_resume_schedule(R, g, psets, n_psets);
        if (e != 0)
            return duel_resume_refused(R, e);
        e = neat_coev_set_params(R->coev, &R->eff.neat, &R->eff.coev);
        if (e) {
            de_err(R, "the overrides do not fit this run (pop_size cannot change): %s\n",
                    neat_strerror(e));
            return duel_resume_refused(R, 2);
        }
    }
    /* the [run] keys the checkpoint does not hold, against what the run wrote: an edit is refused, naming the key,
     * unless this resume gives the same change the right way (as the parameters above) */
    {
        /* an edit is one the seal does not explain and this resume does not give again as an override */
        int g_edit = sealed < 0 && c == 0 && before.generations != seal_gens &&
                     !((have_gens || duel_sets_key(sets, n_sets, "generations")) &&
                       R->cfg.generations == before.generations);
        int e_edit = sealed < 0 && c == 0 && before.strength_every != seal_every &&
                     !(duel_sets_key(sets, n_sets, "strength_every") && R->cfg.strength_every == before.strength_every);
        if (g_edit || e_edit) {
            de_err(R, "%s/config.ini says '%s = %u' but the run wrote '%s = %u': a hand edit of "
                            "config.ini is not taken (give a change as %s, which is applied and logged, or restore "
                            "config.ini)\n", de_esc(R, R->dir), g_edit ? "generations" : "strength_every",
                    g_edit ? before.generations : before.strength_every, g_edit ? "generations" : "strength_every",
                    g_edit ? seal_gens : seal_every, g_edit ? "resume --generations N" : "--set strength_every=K");
            return duel_resume_refused(R, 2);
        }
    }
    /* a run from before the rules were data carries them from now on */
    if (de_tag_run(R) != 0) {
        de_err(R, "cannot resume: out of memory\n");
        return duel_resume_refused(R, 1);
    }
    g = de_next_gen(R);
    /* rows written after the checkpoint belong to a generation that runs
     * again: generations.csv keeps the generations before it, dominance.csv
     * (whose first field is the level) the levels it holds */
    /* nothing is cut before the records are known to be whole */
    if (R->coev != NULL && (k = (uint32_t)de_check_generations(R, g)) != 0)
        return duel_resume_refused(R, (int)k);
    de_path(path, sizeof path, R->dir, "generations.csv");
    if (duel_csv_keep_before(path, g) != 0) {
        de_err(R, "%s: cannot rewrite: %s\n", de_esc(R, path), duel_file_strerror(errno));
        return duel_resume_refused(R, 1);
    }
    de_path(path, sizeof path, R->dir, "strength.csv");
    if (duel_csv_keep_before(path, g) != 0) {
        de_err(R, "%s: cannot rewrite: %s\n", de_esc(R, path), duel_file_strerror(errno));
        return duel_resume_refused(R, 1);
    }
    if ((R->coev != NULL && (e = de_rebuild_dominance(R)) != 0) || (e = de_rebuild_strength(R, g)) != 0)
        return duel_resume_refused(R, e);
    if (n_sets > 0 && g >= R->cfg.generations) {
        /* it would reach config.ini and never the checkpoint: the next resume would find them disagreeing */
        de_err(R, "resume: the run has played its %u generations: an override (--set) applies to "
                        "generations to come; give --generations N with it to extend the run\n", g);
        return duel_resume_refused(R, 2);
    }
    for (k = 0; k < n_sets; k++)
        de_log(R, "resume: override %s", sets[k]);
    if (g > R->cfg.generations) {
        de_err(R, "resume: the run has played %u generations already, more than %u\n", g,
                R->cfg.generations);
        return duel_resume_refused(R, 2);
    }
    if (R->cfg.generations != before.generations) {
        const char *how = R->cfg.generations > before.generations ? "extended" : "shortened";
        de_log(R, "resume: generations %u -> %u (%s; config.ini now says %u)", before.generations,
                 R->cfg.generations, how, R->cfg.generations);
        de_say(R, DUEL_SAY_INFO, "%s %s from %u to %u generations (stored in config.ini)", de_esc(R, R->dir), how,
               before.generations, R->cfg.generations);
    }
    if (de_write_config(R) != 0)
        return duel_resume_refused(R, 1);
    {
        char th[64];
        de_threads_words(R->threads, th, sizeof th);
        de_log(R, "resume at generation %u of %u, %s", g, R->cfg.generations, th);
    }
    de_say(R, DUEL_SAY_INFO, "resuming %s at generation %u of %u", de_esc(R, R->dir), g, R->cfg.generations);
    if ((e = de_go(R)) != 0)
        return duel_resume_refused(R, e);
    *out = R;
    return 0;
}
