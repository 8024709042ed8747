/* cartpole.c - double-pole cart dynamics (constants from the NEAT C++ 1.2.1 release, see docs/parameters.md). */
#include <math.h>

#include "cartpole.h"

#define CP_GRAVITY (-9.8)
#define CP_MASS_CART 1.0
#define CP_MASS_POLE1 0.1
#define CP_MASS_POLE2 0.01
#define CP_HALF_LEN1 0.5
#define CP_HALF_LEN2 0.05
#define CP_MUP 0.000002 /* pole hinge friction */
#define CP_TAU 0.01
#define CP_THIRTY_SIX_DEG 0.628329

void cartpole_init(cartpole *c)
{
    int i;
    for (i = 0; i < 6; i++)
        c->s[i] = 0.0;
    c->s[2] = 0.07;
}

static void cp_derivs(double force, const double *st, double *d)
{
    double c1 = cos(st[2]), s1 = sin(st[2]), c2 = cos(st[4]), s2 = sin(st[4]);
    double ml1 = CP_HALF_LEN1 * CP_MASS_POLE1, ml2 = CP_HALF_LEN2 * CP_MASS_POLE2;
    double t1 = CP_MUP * st[3] / ml1, t2 = CP_MUP * st[5] / ml2;
    double f1 = ml1 * st[3] * st[3] * s1 + 0.75 * CP_MASS_POLE1 * c1 * (t1 + CP_GRAVITY * s1);
    double f2 = ml2 * st[5] * st[5] * s2 + 0.75 * CP_MASS_POLE2 * c2 * (t2 + CP_GRAVITY * s2);
    double m1 = CP_MASS_POLE1 * (1.0 - 0.75 * c1 * c1);
    double m2 = CP_MASS_POLE2 * (1.0 - 0.75 * c2 * c2);
    double xacc = (force + f1 + f2) / (m1 + m2 + CP_MASS_CART);
    d[0] = st[1];
    d[1] = xacc;
    d[2] = st[3];
    d[3] = -0.75 * (xacc * c1 + CP_GRAVITY * s1 + t1) / CP_HALF_LEN1;
    d[4] = st[5];
    d[5] = -0.75 * (xacc * c2 + CP_GRAVITY * s2 + t2) / CP_HALF_LEN2;
}

static void cp_rk4(double force, double *st)
{
    double k1[6], k2[6], k3[6], k4[6], tmp[6];
    int i;
    cp_derivs(force, st, k1);
    for (i = 0; i < 6; i++)
        tmp[i] = st[i] + 0.5 * CP_TAU * k1[i];
    cp_derivs(force, tmp, k2);
    for (i = 0; i < 6; i++)
        tmp[i] = st[i] + 0.5 * CP_TAU * k2[i];
    cp_derivs(force, tmp, k3);
    for (i = 0; i < 6; i++)
        tmp[i] = st[i] + CP_TAU * k3[i];
    cp_derivs(force, tmp, k4);
    for (i = 0; i < 6; i++)
        st[i] += CP_TAU / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
}

void cartpole_act(cartpole *c, double force)
{
    cp_rk4(force, c->s);
    cp_rk4(force, c->s);
}

int cartpole_failed(const cartpole *c)
{
    return fabs(c->s[0]) > 2.4 || fabs(c->s[2]) > CP_THIRTY_SIX_DEG || fabs(c->s[4]) > CP_THIRTY_SIX_DEG;
}
