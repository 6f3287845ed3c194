# Helpers shared by all modules.

# Unity builds of the libraries: the translation units of one library compiled in batches of
# GEARFEM_UNITY_BATCH, so that the headers and template instantiations they share are compiled
# once per batch (validation/RESULTS.md, fresh set-up). A helper in an anonymous namespace is
# then visible to the other files of its batch: give such helpers a name of their own, or put
# them in a header.
option(GEARFEM_UNITY "Compile each library in unity batches (faster clean builds)" ON)
set(GEARFEM_UNITY_BATCH 8 CACHE STRING "Translation units per unity batch")

function(gearfem_unity target)
  if(GEARFEM_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${GEARFEM_UNITY_BATCH})
  endif()
endfunction()

# gearfem_light_library(NAME SOURCES...): a module with no deal.II (Eigen only).
function(gearfem_light_library name)
  add_library(${name} STATIC ${ARGN})
  gearfem_unity(${name})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR}/lib ${PROJECT_BINARY_DIR}/generated)
  target_compile_options(${name} PRIVATE -Wall -Wextra -Wno-unused-parameter)
  target_link_libraries(${name} PUBLIC Eigen3::Eigen)
endfunction()

# Precompiled deal.II headers. Every deal.II translation unit parses the same ~200k lines
# of deal.II/Boost/Trilinos headers; with one precompiled header per flag set, reused by
# every deal.II target (REUSE_FROM), a clean build parses them twice instead of ~50 times.
# GCC accepts a PCH only with the same PIC/PIE setting: libraries use the -fPIC host,
# executables the host without PIC flags (Debian's GCC defaults to PIE for both).
option(GEARFEM_PCH "Precompile the common deal.II headers (faster clean builds)" ON)
set(GEARFEM_DEALII_PCH_HEADERS
  <deal.II/base/parameter_handler.h> <deal.II/base/point.h> <deal.II/base/tensor.h>
  <deal.II/base/quadrature_lib.h> <deal.II/base/timer.h> <deal.II/base/utilities.h>
  <deal.II/grid/tria.h> <deal.II/grid/tria_accessor.h> <deal.II/grid/tria_iterator.h>
  <deal.II/dofs/dof_handler.h> <deal.II/fe/fe_q.h> <deal.II/fe/fe_system.h>
  <deal.II/fe/fe_values.h> <deal.II/lac/vector.h> <deal.II/lac/sparse_matrix.h>
  <deal.II/lac/dynamic_sparsity_pattern.h>
  <vector> <string> <map> <memory> <functional> <algorithm> <cmath> <sstream> <iostream>)

function(gearfem_make_dealii_pch_hosts)
  if(NOT GEARFEM_PCH OR TARGET gearfem_pch_pic)
    return()
  endif()
  set(src ${PROJECT_BINARY_DIR}/generated/pch_host.cc)
  if(NOT EXISTS ${src})
    file(WRITE ${src} "// Host translation unit of the precompiled deal.II headers.\n")
  endif()
  foreach(host pic exe)
    add_library(gearfem_pch_${host} OBJECT ${src})
    target_include_directories(gearfem_pch_${host} SYSTEM PUBLIC ${DEAL_II_INCLUDE_DIRS})
    target_precompile_headers(gearfem_pch_${host} PRIVATE ${GEARFEM_DEALII_PCH_HEADERS})
    # Every deal.II target links gearfem_base and so Boost::headers, whose BOOST_ALL_NO_LIB
    # is tested in the Boost headers that deal.II includes; GCC rejects a PCH built without it.
    target_compile_definitions(gearfem_pch_${host} PRIVATE BOOST_ALL_NO_LIB)
  endforeach()
  set_target_properties(gearfem_pch_pic PROPERTIES POSITION_INDEPENDENT_CODE ON)
  set_target_properties(gearfem_pch_exe PROPERTIES POSITION_INDEPENDENT_CODE OFF)
endfunction()

function(gearfem_reuse_dealii_pch target)
  if(NOT GEARFEM_PCH)
    return()
  endif()
  gearfem_make_dealii_pch_hosts()
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "EXECUTABLE")
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE OFF)
    target_precompile_headers(${target} REUSE_FROM gearfem_pch_exe)
  else()
    target_precompile_headers(${target} REUSE_FROM gearfem_pch_pic)
  endif()
endfunction()

# gearfem_use_dealii(TARGET): compile and link TARGET against the release deal.II.
# We do not use DEAL_II_SETUP_TARGET because its flags carry -g, which doubles the
# build time of deal.II translation units on the 2-core machine.
function(gearfem_use_dealii target)
  target_include_directories(${target} SYSTEM PUBLIC ${DEAL_II_INCLUDE_DIRS})
  gearfem_reuse_dealii_pch(${target})
  # The imported target alone resolves to a bare -ldeal.ii; the full list carries
  # Trilinos, PETSc, MPI, gmsh, HDF5 and the rest that deal.II's headers pull in.
  target_link_libraries(${target} PUBLIC ${DEAL_II_LIBRARIES_RELEASE})
  target_compile_options(${target} PRIVATE -Wno-unused-parameter)
endfunction()

# gearfem_dealii_library(NAME SOURCES...): a module built on deal.II.
function(gearfem_dealii_library name)
  add_library(${name} STATIC ${ARGN})
  gearfem_unity(${name})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR}/lib ${PROJECT_BINARY_DIR}/generated)
  target_compile_options(${name} PRIVATE -Wall -Wextra)
  gearfem_use_dealii(${name})
endfunction()

# gearfem_unit_test(NAME LABEL SOURCES... LIBS ...): a GoogleTest executable registered with CTest.
function(gearfem_unit_test name label)
  cmake_parse_arguments(T "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main)
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/tests/unit)
  target_compile_definitions(${name} PRIVATE GEARFEM_TEST_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  add_test(NAME ${name} COMMAND ${name} --gtest_brief=1)
  set_tests_properties(${name} PROPERTIES LABELS "${label}"
    ENVIRONMENT "GEARFEM_SOURCE_DIR=${PROJECT_SOURCE_DIR};GEARFEM_BINARY_DIR=${PROJECT_BINARY_DIR}")
endfunction()
