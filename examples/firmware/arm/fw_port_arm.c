/* fw_port_arm.c - the Cortex-M port: the semihosting trap (BKPT 0xAB), SysTick as the counter, the calibration loop. */
#include "fw_port.h"

/* SysTick (Armv6-M and Armv7-M system control space). */
#define FW_SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define FW_SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define FW_SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define FW_SYST_ENABLE 1u
#define FW_SYST_CLKSOURCE_CPU 4u

/* DWT cycle counter (Armv7-M: debug unit, enabled through DEMCR.TRCENA). */
#define FW_DEMCR (*(volatile uint32_t *)0xE000EDFCu)
#define FW_DEMCR_TRCENA (1u << 24)
#define FW_DWT_CTRL (*(volatile uint32_t *)0xE0001000u)
#define FW_DWT_CTRL_CYCCNTENA 1u
#define FW_DWT_CYCCNT (*(volatile uint32_t *)0xE0001004u)

const uint32_t fw_port_counter_mask = 0xFFFFFFu; /* 24 bits */

/* A semihosting call: BKPT 0xAB with the operation in r0 and its argument
 * in r1; the result comes back in r0. */
uint32_t fw_semihost(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void fw_port_counter_start(void)
{
    FW_SYST_RVR = 0xFFFFFFu;
    FW_SYST_CVR = 0; /* any write clears it */
    FW_SYST_CSR = FW_SYST_ENABLE | FW_SYST_CLKSOURCE_CPU;
#if __ARM_ARCH >= 7
    FW_DEMCR |= FW_DEMCR_TRCENA;
    FW_DWT_CYCCNT = 0;
    FW_DWT_CTRL |= FW_DWT_CTRL_CYCCNTENA;
#endif
}

int fw_port_cycles(uint32_t *value)
{
#if __ARM_ARCH >= 7
    *value = FW_DWT_CYCCNT;
    return 0;
#else
    (void)value;
    return -1; /* Armv6-M has no DWT cycle counter */
#endif
}

uint32_t fw_port_counter(void)
{
    /* SysTick counts down */
    return (0xFFFFFFu - FW_SYST_CVR) & 0xFFFFFFu;
}

void fw_port_spin(uint32_t n)
{
    /* two instructions per iteration: subs, bne (GCC hands Thumb-1 inline
     * assembly over in divided syntax: unified says what is meant) */
    __asm__ volatile(".syntax unified\n"
                     "1: subs %0, %0, #1\n"
                     "   bne 1b\n"
                     : "+l"(n)
                     :
                     : "cc");
}
