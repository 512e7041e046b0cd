# Issue 7 suites: nonlinear statics and forced response of the chain.
ringvib_test(multibody_dynamics_unit_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_dynamics_model.cpp
  LIBS multibody LABELS unit)
ringvib_test(multibody_dynamics_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_dynamics.cpp
  LIBS multibody LABELS validation)
ringvib_test(multibody_statics_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_statics.cpp
  LIBS multibody LABELS validation)
ringvib_test(multibody_dynamics_stress_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_dynamics_stress.cpp
  LIBS multibody LABELS stress)
# Issue 8 point 2: the O(n) path of the forced response.
ringvib_test(multibody_dynamics_sparse_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_dynamics_sparse.cpp
  LIBS multibody LABELS validation)
ringvib_test(multibody_dynamics_sparse_stress_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_dynamics_sparse_stress.cpp
  LIBS multibody LABELS stress)
