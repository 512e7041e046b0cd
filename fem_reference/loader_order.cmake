# The FE plug-in's start is the dynamic loader binding ~320k symbols across the ~200
# libraries deal.II pulls in (bench/process.sh, the tiny FE scene). Each lookup walks the
# plug-in's breadth-first search list until a library defines the symbol, so its cost is
# the defining library's place in that list, and Debian's list puts libraries that bind
# thousands of their own symbols (gmsh, OpenCASCADE, Teuchos) a hundred places deep.
#
# ringvib_order_loader_scope(target library) lists library's dependency closure in the
# target's DT_NEEDED, most-bound first: the search list then starts with them. The counts
# come from the loader itself (`LD_DEBUG=bindings ldd -r`, which prints the loader's trace
# on stdout; about 1 s, once per configure and cached). Only the order changes: the same
# libraries load, and a symbol that several of them define (vague linkage, identical by the
# ODR) may bind to another identical copy. When the probe fails the target links as before.
# Measured: docs/measured.md, "The FE plug-in's start".
function(ringvib_order_loader_scope target library)
  if(NOT CMAKE_SYSTEM_NAME STREQUAL "Linux")
    return()
  endif()
  if(NOT RINGVIB_LOADER_ORDER_FOR STREQUAL library)  # unset on the first configure
    # The C and C++ run-time libraries are in the executable's global scope, searched before
    # the plug-in's list; the loader and the vDSO (no path) cannot be linked.
    execute_process(
      COMMAND sh -c "LD_DEBUG=bindings ldd -r '${library}' 2>/dev/null \
        | awk '/binding file/ { sub(/.* to /, \"\"); sub(/ \\[.*/, \"\"); n[$0]++ } \
               END { for (l in n) print n[l], l }' \
        | sort -rn | awk '$2 ~ /^\\// { print $2 }' \
        | grep -v -E '/(ld-linux[^/]*|libc|libm|libstdc\\+\\+|libgcc_s)\\.so'"
      OUTPUT_VARIABLE _order
      RESULT_VARIABLE _status)
    string(REGEX REPLACE "\n$" "" _order "${_order}")
    string(REPLACE "\n" ";" _order "${_order}")
    if(NOT _status EQUAL 0 OR NOT _order)
      message(STATUS "FE plug-in: library order probe failed (${_status}); linking in deal.II's order")
      set(_order "")
    endif()
    set(RINGVIB_LOADER_ORDER "${_order}" CACHE INTERNAL "deal.II's dependency closure, most-bound first")
    set(RINGVIB_LOADER_ORDER_FOR "${library}" CACHE INTERNAL "the library RINGVIB_LOADER_ORDER is for")
  endif()
  if(RINGVIB_LOADER_ORDER)
    list(LENGTH RINGVIB_LOADER_ORDER _count)
    message(STATUS "FE plug-in: ${_count} libraries linked most-bound first")
    target_link_options(${target} PRIVATE "LINKER:--no-as-needed" ${RINGVIB_LOADER_ORDER} "LINKER:--as-needed")
  endif()
endfunction()
