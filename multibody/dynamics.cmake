# Issue 7 (nonlinear statics and dynamics): sources of the multibody library.
# multibody/CMakeLists.txt globs *.cpp, which already picks these up; add them only if
# that glob is ever replaced by an explicit list.
get_target_property(_ringvib_mb_sources multibody SOURCES)
foreach(_f dynamics.cpp dynamics_model.cpp statics.cpp)
  if(NOT "${_ringvib_mb_sources}" MATCHES "${_f}")
    target_sources(multibody PRIVATE ${CMAKE_CURRENT_LIST_DIR}/${_f})
  endif()
endforeach()
