# 32-bit Arm, hard float (Raspberry Pi OS 32-bit, Bela's Debian): cmake --preset armhf
# (build/armhf). Debian's armhf baseline: ARMv7-A, VFPv3-D16, Thumb-2, no NEON assumed.
set(TACTUS_CROSS_TRIPLET arm-linux-gnueabihf)
set(TACTUS_CROSS_PROCESSOR armv7l)
set(TACTUS_QEMU qemu-arm-static)
include(${CMAKE_CURRENT_LIST_DIR}/toolchain-debian-cross.cmake)
