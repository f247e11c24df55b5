# The layering of src/ (docs/architecture.md), checked on every test run:
#   cmake -DSOURCE_DIR=<dir holding src/> -P check_layering.cmake
# Every `#include "layer/file"` of a file in src/<layer>/ must name a layer that <layer> may
# use, and so must every project header it reaches through other project headers (so that,
# e.g., no header of model/ that analysis/ includes drags in language/). Fails listing each
# violation with the chain of includes that leads to it; fails as well when it checked no file.

cmake_minimum_required(VERSION 3.20)

# May use (besides itself). app may use everything.
set(allowed_common "")
set(allowed_language "common")
set(allowed_expr "common")
set(allowed_user "expr;common")
set(allowed_model "language;expr;user;common")
set(allowed_mechanics "model;expr;user;common")
set(allowed_solvers "common")
set(allowed_output "model;expr;user;common")
set(allowed_analysis "output;solvers;mechanics;model;expr;user;common")
set(allowed_commands "analysis;output;solvers;mechanics;model;language;expr;user;common")
# api (the embeddable API of the Python package) runs command files with app's CommandRunner.
set(allowed_api "app;commands;analysis;output;solvers;mechanics;model;language;expr;user;common")
set(layers common language expr user model mechanics solvers output analysis commands api)

if(NOT SOURCE_DIR)
  message(FATAL_ERROR "check_layering: pass -DSOURCE_DIR=<directory holding src/>")
endif()

# The project includes ("layer/file.hpp") of one file, as paths relative to src/.
function(project_includes file out)
  file(STRINGS "${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"[a-z_]+/[^\"]+\"")
  set(result "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" inc "${line}")
    list(APPEND result "${inc}")
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

set(checked 0)
set(violations 0)
foreach(layer IN LISTS layers)
  set(ok "${layer};${allowed_${layer}}")
  file(GLOB files "${SOURCE_DIR}/src/${layer}/*.hpp" "${SOURCE_DIR}/src/${layer}/*.cpp"
       "${SOURCE_DIR}/src/${layer}/*.h")
  foreach(file IN LISTS files)
    math(EXPR checked "${checked} + 1")
    file(RELATIVE_PATH start "${SOURCE_DIR}/src" "${file}")
    # Breadth-first over the project headers reachable from this file; `via_<header>` keeps
    # the header that first included it, to print the chain.
    set(queue "${start}")
    set(seen "${start}")
    while(queue)
      list(POP_FRONT queue current)
      if(NOT EXISTS "${SOURCE_DIR}/src/${current}")
        continue()  # a generated or third-party header: not a layer of src/
      endif()
      project_includes("${SOURCE_DIR}/src/${current}" incs)
      foreach(inc IN LISTS incs)
        string(REGEX REPLACE "/.*" "" target "${inc}")
        list(FIND ok "${target}" found)
        if(found EQUAL -1 AND EXISTS "${SOURCE_DIR}/src/${target}")
          set(chain "${inc} <- ${current}")
          set(back "${current}")
          while(DEFINED via_${back})
            set(back "${via_${back}}")
            string(APPEND chain " <- ${back}")
          endwhile()
          message(NOTICE "layering: src/${layer} may not use ${target}/: ${chain}")
          math(EXPR violations "${violations} + 1")
        endif()
        list(FIND seen "${inc}" known)
        if(known EQUAL -1)
          list(APPEND seen "${inc}")
          list(APPEND queue "${inc}")
          set(via_${inc} "${current}")
        endif()
      endforeach()
    endwhile()
    foreach(s IN LISTS seen)
      unset(via_${s})
    endforeach()
  endforeach()
endforeach()

if(checked EQUAL 0)
  message(FATAL_ERROR "layering: no source file found under ${SOURCE_DIR}/src")
endif()
if(violations GREATER 0)
  message(FATAL_ERROR "layering: ${violations} upward include(s) in ${checked} files")
endif()
message(STATUS "layering: ${checked} files checked, every include follows the layers")
