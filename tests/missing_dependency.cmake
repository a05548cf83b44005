# Configures the project with one dependency hidden (CMAKE_DISABLE_FIND_PACKAGE_
# <package>) and passes only when the configure step fails with the message
# that names the package to install on every system (cmake/dependencies.cmake).
#
#   cmake -DROOT=<source> -DBUILD=<scratch dir> -DGENERATOR=<name> -DPACKAGE=<package>
#         -DEXPECT=<regex;regex...> [-DOPTIONS=<-Dvar=value;...>] -P missing_dependency.cmake
# The tests and the book are off unless OPTIONS turns one on (for a dependency
# that only they have).
foreach(var ROOT BUILD GENERATOR PACKAGE EXPECT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "missing_dependency.cmake: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE ${BUILD})
execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${ROOT} -B ${BUILD} -G ${GENERATOR} -DCMAKE_DISABLE_FIND_PACKAGE_${PACKAGE}=ON
          -DVKT_BUILD_TESTS=OFF -DVKT_BUILD_BOOK=OFF ${OPTIONS}
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
file(REMOVE_RECURSE ${BUILD})
message("${err}")

if(status EQUAL 0)
  message(FATAL_ERROR "the configure step succeeded without ${PACKAGE}")
endif()
foreach(pattern IN LISTS EXPECT)
  if(NOT err MATCHES "${pattern}")
    message(FATAL_ERROR "the configure step failed, but its message does not match '${pattern}'")
  endif()
endforeach()
message("without ${PACKAGE}, the configure step stops and names its packages")
