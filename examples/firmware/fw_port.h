/* fw_port.h - what each target (arm/, riscv/, the host) gives the firmware example: console output, exit, a counter. */
#ifndef FW_PORT_H
#define FW_PORT_H

#include <stddef.h>
#include <stdint.h>

/* Exit statuses of the firmware and of its host twin. */
#define FW_EXIT_OK 0      /* every game played */
#define FW_EXIT_FAILED 1  /* a game could not be played (duel_play error) */
#define FW_EXIT_REFUSED 2 /* a linked champion was refused (bad blob, wrong shape, no memory) */
#define FW_EXIT_FAULT 3   /* a processor fault or trap (targets only) */

/* One semihosting call (operation, argument block; the result), by the
 * port's own trap instruction: fw_semihosting.c builds console output and
 * exit on it. */
uint32_t fw_semihost(uint32_t op, const void *arg);

/* n bytes to the host's console (semihosting on the targets). */
void fw_port_write(const char *s, size_t n);

/* Ends the program with status (semihosting SYS_EXIT_EXTENDED on the
 * targets, so QEMU exits with it). Never returns. */
void fw_port_exit(int status);

/* A free-running counter for fw_figures.c, in the port's own units (SysTick
 * ticks on Cortex-M, minstret on RISC-V); differences are taken modulo
 * fw_port_counter_mask + 1. fw_port_counter_start starts it. */
void fw_port_counter_start(void);
uint32_t fw_port_counter(void);
extern const uint32_t fw_port_counter_mask;

/* The core's own cycle counter (DWT CYCCNT on Armv7-M, mcycle on RISC-V),
 * started by fw_port_counter_start: returns 0 and its value, or -1 where the
 * core has none (Armv6-M). */
int fw_port_cycles(uint32_t *value);

/* Executes exactly FW_PORT_SPIN_INSNS * n instructions in a loop (n >= 1):
 * fw_figures.c converts counter units into instructions with it. */
#define FW_PORT_SPIN_INSNS 2
void fw_port_spin(uint32_t n);

#endif /* FW_PORT_H */
