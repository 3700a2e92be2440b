# Cross-compiling for aarch64 Linux with Debian's crossbuild-essential-arm64 and the arm64
# libraries of multiarch (tools/cross_cpu/build-aarch64 installs both).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
# Run the programs the build makes (key generation is Python; nothing else runs) under qemu.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64)
# pkg-config (FindOpenSSL asks it first) must describe the arm64 libraries, not the build
# machine's.
set(ENV{PKG_CONFIG_LIBDIR} /usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig)
