// neatcpp_genome.cpp - NEAT::Genome <-> neat_genome: renumbered to libneat's layout, or with the historical markings kept, and a start the other way.
#include "neatcpp_genome.h"

#include <map>
#include <vector>

#include "gene.h"
#include "genome.h"
#include "link.h"
#include "nnode.h"
#include "trait.h"

int neatcpp_genome_shape(const NEAT::Genome *g, uint32_t *n_inputs, uint32_t *n_outputs)
{
    uint32_t bias = 0, in = 0, out = 0;
    for (std::vector<NEAT::NNode *>::const_iterator it = g->nodes.begin(); it != g->nodes.end(); ++it) {
        switch ((*it)->gen_node_label) {
        case NEAT::BIAS: bias++; break;
        case NEAT::INPUT: in++; break;
        case NEAT::OUTPUT: out++; break;
        default: break;
        }
    }
    *n_inputs = in;
    *n_outputs = out;
    return bias == 1 && out > 0 ? NEAT_OK : NEAT_E_ARG;
}

int neatcpp_genome_convert(const NEAT::Genome *g, neat_genome *out, uint32_t *clamped)
{
    // the release's node_id -> our id; its nodes are kept sorted by node_id,
    // and genes point at them (gene.h: lnk->in_node, lnk->out_node)
    std::map<int, uint32_t> id;
    uint32_t n_in = 0, n_out = 0, next_in = 1, next_out, next_hidden, innov = 0;
    int err = neatcpp_genome_shape(g, &n_in, &n_out);

    neat_genome_init(out);
    if (err)
        return err;
    next_out = n_in + 1;
    next_hidden = n_in + n_out + 1;
    for (std::vector<NEAT::NNode *>::const_iterator it = g->nodes.begin(); it != g->nodes.end() && !err; ++it) {
        uint32_t ours;
        int type;
        switch ((*it)->gen_node_label) {
        case NEAT::BIAS: ours = 0; type = NEAT_NODE_BIAS; break;
        case NEAT::INPUT: ours = next_in++; type = NEAT_NODE_INPUT; break;
        case NEAT::OUTPUT: ours = next_out++; type = NEAT_NODE_OUTPUT; break;
        default: ours = next_hidden++; type = NEAT_NODE_HIDDEN; break;
        }
        if (id.count((*it)->node_id))
            err = NEAT_E_ARG; // two nodes with one id: not a genome the release made
        else
            err = neat_genome_add_node(out, ours, type, NULL);
        id[(*it)->node_id] = ours;
    }
    for (std::vector<NEAT::Gene *>::const_iterator it = g->genes.begin(); it != g->genes.end() && !err; ++it) {
        const NEAT::Link *l = (*it)->lnk;
        std::map<int, uint32_t>::const_iterator a = id.find(l->in_node->node_id), b = id.find(l->out_node->node_id);
        double w = l->weight;
        if (a == id.end() || b == id.end()) {
            err = NEAT_E_ARG;
            break;
        }
        // the blob stores Q3.12 (it saturates just inside +-8 anyway); a weight
        // beyond 8 would mean the two engines' networks differ by more than rounding
        if (w > 8.0 || w < -8.0) {
            w = w > 0 ? 8.0 : -8.0;
            ++*clamped;
        }
        err = neat_genome_add_conn(out, a->second, b->second, w, innov++, (*it)->enable ? 1 : 0, NULL);
    }
    if (err)
        neat_genome_free(out, NULL);
    return err;
}

// g's node of that id, or NULL (libneat's own lookup is internal)
static const neat_node *find_node(const neat_genome *g, long id)
{
    uint32_t i;
    for (i = 0; i < g->n_nodes; i++)
        if ((long)g->nodes[i].id == id)
            return &g->nodes[i];
    return NULL;
}

int neatcpp_genome_convert_ids(const NEAT::Genome *g, neat_genome *out, uint32_t *dropped)
{
    int err = NEAT_OK;
    neat_genome_init(out);
    for (std::vector<NEAT::NNode *>::const_iterator it = g->nodes.begin(); it != g->nodes.end() && !err; ++it) {
        int type;
        switch ((*it)->gen_node_label) {
        case NEAT::BIAS: type = NEAT_NODE_BIAS; break;
        case NEAT::INPUT: type = NEAT_NODE_INPUT; break;
        case NEAT::OUTPUT: type = NEAT_NODE_OUTPUT; break;
        default: type = NEAT_NODE_HIDDEN; break;
        }
        if ((*it)->node_id < 1) {
            err = NEAT_E_ARG;
        } else if (find_node(out, (*it)->node_id - 1) != NULL) {
            // a node id the genome has already: the release can make one when a child of this generation,
            // taken as a later species' parent, has a link split again (docs/neat-cpp.md); libneat's genome
            // holds each id once, and the genes name the node by its id, so the one node serves them all
            ++*dropped;
        } else {
            err = neat_genome_add_node(out, (uint32_t)((*it)->node_id - 1), type, NULL);
        }
    }
    for (std::vector<NEAT::Gene *>::const_iterator it = g->genes.begin(); it != g->genes.end() && !err; ++it) {
        const NEAT::Link *l = (*it)->lnk;
        double innov = (*it)->innovation_num, w = l->weight;
        if (innov < 1.0 || innov != (double)(uint32_t)innov || l->in_node->node_id < 1 || l->out_node->node_id < 1) {
            err = NEAT_E_ARG;
            break;
        }
        if (w > 8.0 || w < -8.0)
            w = w > 0 ? 8.0 : -8.0; // the release caps its weights at +-8: never reached
        err = neat_genome_add_conn(out, (uint32_t)(l->in_node->node_id - 1), (uint32_t)(l->out_node->node_id - 1), w,
                                   (uint32_t)innov - 1u, (*it)->enable ? 1 : 0, NULL);
        if (err == NEAT_E_ARG && find_node(out, l->in_node->node_id - 1) &&
            find_node(out, l->out_node->node_id - 1)) {
            ++*dropped; // the innovation number again: libneat's genome holds it once
            err = NEAT_OK;
        }
    }
    if (err)
        neat_genome_free(out, NULL);
    return err;
}

NEAT::Genome *neatcpp_genome_from_libneat(const neat_genome *g)
{
    std::vector<NEAT::Trait *> traits;
    std::vector<NEAT::NNode *> nodes;
    std::vector<NEAT::Gene *> genes;
    std::map<uint32_t, NEAT::NNode *> by_id;
    NEAT::Trait *t = new NEAT::Trait(1, 0, 0, 0, 0, 0, 0, 0, 0, 0);
    uint32_t i;
    traits.push_back(t);
    for (i = 0; i < g->n_nodes; i++) {
        const neat_node *n = &g->nodes[i];
        NEAT::nodeplace place = n->type == NEAT_NODE_BIAS    ? NEAT::BIAS
                                : n->type == NEAT_NODE_INPUT ? NEAT::INPUT
                                : n->type == NEAT_NODE_OUTPUT ? NEAT::OUTPUT
                                                              : NEAT::HIDDEN;
        NEAT::nodetype kind = n->type == NEAT_NODE_BIAS || n->type == NEAT_NODE_INPUT ? NEAT::SENSOR : NEAT::NEURON;
        NEAT::NNode *node = new NEAT::NNode(kind, (int)n->id + 1, place);
        nodes.push_back(node);
        by_id[n->id] = node;
    }
    for (i = 0; i < g->n_conns; i++) {
        const neat_conn *c = &g->conns[i];
        const neat_node *src = find_node(g, (long)c->in);
        bool back = c->in == c->out || (src != NULL && src->type >= NEAT_NODE_OUTPUT && c->out < c->in);
        NEAT::Gene *gene = new NEAT::Gene(t, c->weight, by_id[c->in], by_id[c->out], back, (double)c->innov + 1.0,
                                          c->weight);
        gene->enable = c->enabled != 0;
        genes.push_back(gene);
    }
    return new NEAT::Genome(1, traits, nodes, genes);
}
