# Run at build time (cmake -P): write version.h with the current git hash, touching the file
# only when its content changes so that nothing rebuilds needlessly.
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY ${SOURCE_DIR}
  OUTPUT_VARIABLE GEARFEM_GIT_HASH OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
execute_process(COMMAND git status --porcelain --untracked-files=no WORKING_DIRECTORY ${SOURCE_DIR}
  OUTPUT_VARIABLE dirty OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT GEARFEM_GIT_HASH)
  set(GEARFEM_GIT_HASH "unknown")
elseif(dirty)
  set(GEARFEM_GIT_HASH "${GEARFEM_GIT_HASH}-dirty")
endif()
configure_file(${SOURCE_DIR}/lib/base/version.h.in ${OUTPUT}.new @ONLY)
file(READ ${OUTPUT}.new new_content)
set(old_content "")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old_content)
endif()
if(NOT new_content STREQUAL old_content)
  file(RENAME ${OUTPUT}.new ${OUTPUT})
else()
  file(REMOVE ${OUTPUT}.new)
endif()
