/* duel_main.c - duel_evolve's main: the command is duel_evolve_main (duel_evolve.c), which other programs call too. */
#include "duel_cli.h"

int main(int argc, char **argv)
{
    return duel_evolve_main(argc, argv);
}
