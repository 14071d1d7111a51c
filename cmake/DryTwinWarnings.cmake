# Warnings and sanitizers, applied through an INTERFACE target so that every
# DryTwin target opts in with target_link_libraries(... PRIVATE drytwin::options).
add_library(drytwin_options INTERFACE)
add_library(drytwin::options ALIAS drytwin_options)
target_compile_options(drytwin_options INTERFACE -Wall -Wextra -Wpedantic)
# Qt 6-clean: refuse API that Qt 5.15 already deprecates (ARCHITECTURE.md).
target_compile_definitions(drytwin_options INTERFACE QT_DISABLE_DEPRECATED_BEFORE=0x050F00)
if(DRYTWIN_SANITIZE)
  target_compile_options(drytwin_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(drytwin_options INTERFACE -fsanitize=address,undefined)
endif()
