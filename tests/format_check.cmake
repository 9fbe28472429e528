# Fails when any C++ source under engine/ or tests/ is not clang-format clean.
file(GLOB_RECURSE sources ${ROOT}/engine/*.cpp ${ROOT}/engine/*.h ${ROOT}/tests/*.cpp ${ROOT}/tests/*.h)
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${sources}
                RESULT_VARIABLE result ERROR_VARIABLE errors)
if(NOT result EQUAL 0)
  string(REGEX MATCHALL "[^\n]*(warning|error):[^\n]*" lines "${errors}")
  list(LENGTH lines count)
  list(SUBLIST lines 0 10 first)
  string(REPLACE ";" "\n" shown "${first}")
  message(FATAL_ERROR "${count} clang-format differences (run 'make format'), first ones:\n${shown}")
endif()
