/* fw_port_arm.c - the Cortex-M port: console and exit through Arm semihosting, SysTick as the counter, the calibration loop. */
#include "fw_port.h"

/* Semihosting operations (Arm "Semihosting for AArch32 and AArch64", v2). */
#define FW_SYS_WRITE0 0x04
#define FW_SYS_EXIT 0x18          /* angel_SWIreason_ReportException */
#define FW_SYS_EXIT_EXTENDED 0x20 /* the same, with an exit status */
#define FW_ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define FW_ADP_STOPPED_RUNTIME_ERROR_UNKNOWN 0x20023u

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
static uint32_t fw_semihost(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void fw_port_write(const char *s, size_t n)
{
    /* SYS_WRITE0 takes a NUL-terminated string: chunks of a small buffer */
    char buf[65];
    size_t i = 0;
    while (i < n) {
        size_t k = 0;
        while (k < sizeof buf - 1 && i < n)
            buf[k++] = s[i++];
        buf[k] = '\0';
        fw_semihost(FW_SYS_WRITE0, buf);
    }
}

void fw_port_exit(int status)
{
    uint32_t block[2];
    block[0] = FW_ADP_STOPPED_APPLICATION_EXIT;
    block[1] = (uint32_t)status;
    fw_semihost(FW_SYS_EXIT_EXTENDED, block);
    /* a host without SYS_EXIT_EXTENDED: plain SYS_EXIT, success or not */
    fw_semihost(FW_SYS_EXIT, (const void *)(status == 0 ? FW_ADP_STOPPED_APPLICATION_EXIT
                                                        : FW_ADP_STOPPED_RUNTIME_ERROR_UNKNOWN));
    for (;;)
        __asm__ volatile("wfi");
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
