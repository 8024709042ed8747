/* fw_startup.c - Cortex-M start-up for the firmware example: vector table, reset (data copy, bss clear, main, exit), fault report. */
#include <stdint.h>

#include "fw_port.h"

/* From the linker script (arm/sections.ld). */
extern uint32_t fw_stack_top[];
extern uint32_t fw_data_load[], fw_data_start[], fw_data_end[];
extern uint32_t fw_bss_start[], fw_bss_end[];

int main(void);
void fw_reset(void);
void fw_fault(void);
void fw_fault_report(const uint32_t *frame);

/* An entry of the vector table: the initial stack pointer, or a handler. */
typedef union fw_vector {
    uint32_t *sp;
    void (*handler)(void);
} fw_vector;

/* The 16 entries of the architecture; the example enables no interrupt, so
 * every exception is a fault. */
__attribute__((section(".vectors"), used)) const fw_vector fw_vectors[16] = {
    {.sp = fw_stack_top},
    {.handler = fw_reset},   /* reset */
    {.handler = fw_fault},   /* NMI */
    {.handler = fw_fault},   /* HardFault */
    {.handler = fw_fault},   /* MemManage (v7-M) */
    {.handler = fw_fault},   /* BusFault (v7-M) */
    {.handler = fw_fault},   /* UsageFault (v7-M) */
    {.handler = 0},          /* reserved */
    {.handler = 0},
    {.handler = 0},
    {.handler = 0},
    {.handler = fw_fault},   /* SVCall */
    {.handler = fw_fault},   /* DebugMonitor (v7-M) */
    {.handler = 0},          /* reserved */
    {.handler = fw_fault},   /* PendSV */
    {.handler = fw_fault},   /* SysTick (its interrupt is never enabled) */
};

void fw_reset(void)
{
    uint32_t *src = fw_data_load, *dst;
    for (dst = fw_data_start; dst < fw_data_end;)
        *dst++ = *src++;
    for (dst = fw_bss_start; dst < fw_bss_end;)
        *dst++ = 0;
#if defined(__ARM_FP)
    /* hard-float builds (cortex-m4f): the FPU on (CPACR CP10, CP11 full
     * access) before any floating-point register is touched */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n isb" ::: "memory");
#endif
    fw_port_exit(main());
}

/* Any exception: the main stack pointer at entry points at the stacked frame
 * (r0-r3, r12, lr, pc, xpsr); no C prologue may run before it is read. */
__attribute__((naked)) void fw_fault(void)
{
    __asm__ volatile("mrs r0, msp\n"
                     "ldr r1, =fw_fault_report\n"
                     "bx r1\n"
                     ".ltorg\n");
}

/* Which exception (IPSR) and the faulting PC, then exit with FW_EXIT_FAULT:
 * a test sees a clean failure rather than a hang. */
void fw_fault_report(const uint32_t *frame)
{
    static const char hex[] = "0123456789abcdef";
    char msg[] = "fault: exception 0x00 at pc 0x00000000\n";
    uint32_t ipsr, pc = frame[6];
    int i;

    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    msg[19] = hex[(ipsr >> 4) & 15u];
    msg[20] = hex[ipsr & 15u];
    for (i = 0; i < 8; i++)
        msg[30 + i] = hex[(pc >> (28 - 4 * i)) & 15u];
    fw_port_write(msg, sizeof msg - 1);
    fw_port_exit(FW_EXIT_FAULT);
}
