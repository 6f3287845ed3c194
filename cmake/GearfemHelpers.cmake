# Helpers shared by all modules.

# gearfem_light_library(NAME SOURCES...): a module with no deal.II (Eigen only).
function(gearfem_light_library name)
  add_library(${name} STATIC ${ARGN})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR}/lib ${PROJECT_BINARY_DIR}/generated)
  target_compile_options(${name} PRIVATE -Wall -Wextra -Wno-unused-parameter)
  target_link_libraries(${name} PUBLIC Eigen3::Eigen)
endfunction()

# gearfem_use_dealii(TARGET): compile and link TARGET against the release deal.II.
# We do not use DEAL_II_SETUP_TARGET because its flags carry -g, which doubles the
# build time of deal.II translation units on the 2-core machine.
function(gearfem_use_dealii target)
  target_include_directories(${target} SYSTEM PUBLIC ${DEAL_II_INCLUDE_DIRS})
  # The imported target alone resolves to a bare -ldeal.ii; the full list carries
  # Trilinos, PETSc, MPI, gmsh, HDF5 and the rest that deal.II's headers pull in.
  target_link_libraries(${target} PUBLIC ${DEAL_II_LIBRARIES_RELEASE})
  target_compile_options(${target} PRIVATE -Wno-unused-parameter)
endfunction()

# gearfem_dealii_library(NAME SOURCES...): a module built on deal.II.
function(gearfem_dealii_library name)
  add_library(${name} STATIC ${ARGN})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR}/lib ${PROJECT_BINARY_DIR}/generated)
  target_compile_options(${name} PRIVATE -Wall -Wextra)
  gearfem_use_dealii(${name})
endfunction()

# gearfem_unit_test(NAME LABEL SOURCES... LIBS ...): a GoogleTest executable registered with CTest.
function(gearfem_unit_test name label)
  cmake_parse_arguments(T "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main)
  add_test(NAME ${name} COMMAND ${name} --gtest_brief=1)
  set_tests_properties(${name} PROPERTIES LABELS "${label}"
    ENVIRONMENT "GEARFEM_SOURCE_DIR=${PROJECT_SOURCE_DIR};GEARFEM_BINARY_DIR=${PROJECT_BINARY_DIR}")
endfunction()
