/* cartpole.h - the standard double-pole cart (RK4 at 0.01 s), as in the NEAT and ESP double-pole benchmarks. */
#ifndef CARTPOLE_H
#define CARTPOLE_H

/* state: x, x', theta1, theta1', theta2, theta2' (m, m/s, rad, rad/s) */
typedef struct cartpole {
    double s[6];
} cartpole;

/* all zero but the long pole at 0.07 rad */
void cartpole_init(cartpole *c);
/* force in [-10, 10] N for 0.02 s: two RK4 steps of 0.01 s */
void cartpole_act(cartpole *c, double force);
/* |x| > 2.4 m or either pole beyond 36 degrees */
int cartpole_failed(const cartpole *c);

#endif /* CARTPOLE_H */
