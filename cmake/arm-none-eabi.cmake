# Toolchain for bare-metal Arm Cortex-M (Debian gcc-arm-none-eabi, with libnewlib-arm-none-eabi for
# the C headers: the runtime and duelsim link nothing from a C library but memcpy and memset).
# Pick the core with -DNEAT_ARM_CPU=
#   cortex-m0 | cortex-m0plus (default) | cortex-m3 | cortex-m4 (soft-float ABI) | cortex-m4f (FPU,
#   hard-float ABI) | cortex-m7
# The code uses no floating point either way; the ABI only has to match the firmware it links into.
# Everything is built -ffreestanding; docs/firmware.md has the commands.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
# the choice reaches CMake's compiler checks too
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES NEAT_ARM_CPU)
if(NOT NEAT_ARM_CPU)
  set(NEAT_ARM_CPU cortex-m0plus)
endif()
if(NEAT_ARM_CPU STREQUAL "cortex-m4f")
  set(NEAT_ARM_FLAGS "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
elseif(NEAT_ARM_CPU MATCHES "^cortex-m(0|0plus|3|4|7)$")
  set(NEAT_ARM_FLAGS "-mcpu=${NEAT_ARM_CPU} -mthumb -mfloat-abi=soft")
else()
  message(FATAL_ERROR "NEAT_ARM_CPU=${NEAT_ARM_CPU}: expected cortex-m0, cortex-m0plus, cortex-m3, cortex-m4, "
                      "cortex-m4f or cortex-m7")
endif()
set(CMAKE_C_FLAGS_INIT "${NEAT_ARM_FLAGS} -ffreestanding -ffunction-sections -fdata-sections")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
