/* fw_startup.c - RISC-V start-up for the firmware example: entry (gp, sp, trap vector), reset (data copy, bss clear, main, exit), trap report. */
#include <stdint.h>

#include "fw_port.h"
#include "fw_riscv.h"

/* From the linker script (riscv/sections.ld). */
extern uint32_t fw_data_load[], fw_data_start[], fw_data_end[];
extern uint32_t fw_bss_start[], fw_bss_end[];

int main(void);
void fw_start(void);
void fw_reset(void);
void fw_trap(void);

/* The first instruction of the image (the machine jumps to the start of
 * flash): global pointer and stack pointer, trap vector, then C. No C code
 * may run before sp is set, hence naked. */
__attribute__((naked, section(".text.fw_start"))) void fw_start(void)
{
    __asm__ volatile(".option push\n"
                     ".option norelax\n"
                     "la gp, __global_pointer$\n"
                     ".option pop\n"
                     "la sp, fw_stack_top\n"
                     "la t0, fw_trap\n"
                     FW_ZICSR("csrw mtvec, t0")
                     "j fw_reset\n");
}

void fw_reset(void)
{
    uint32_t *src = fw_data_load, *dst;
    for (dst = fw_data_start; dst < fw_data_end;)
        *dst++ = *src++;
    for (dst = fw_bss_start; dst < fw_bss_end;)
        *dst++ = 0;
    fw_port_exit(main());
}

/* Any trap (mtvec, direct mode: 4-byte aligned): its cause and the faulting
 * PC, then exit with FW_EXIT_FAULT, so a test sees a clean failure. */
__attribute__((aligned(4))) void fw_trap(void)
{
    static const char hex[] = "0123456789abcdef";
    char msg[] = "trap: mcause 0x00000000 at pc 0x00000000\n";
    uint32_t cause, pc;
    int i;

    __asm__ volatile(FW_ZICSR("csrr %0, mcause") : "=r"(cause));
    __asm__ volatile(FW_ZICSR("csrr %0, mepc") : "=r"(pc));
    for (i = 0; i < 8; i++) {
        msg[15 + i] = hex[(cause >> (28 - 4 * i)) & 15u];
        msg[32 + i] = hex[(pc >> (28 - 4 * i)) & 15u];
    }
    fw_port_write(msg, sizeof msg - 1);
    fw_port_exit(FW_EXIT_FAULT);
}
