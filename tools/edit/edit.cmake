# Included by tools/plot/CMakeLists.txt after tools/view/view.cmake (its npm ci fetches uPlot and
# math.js). The page of `koppel edit`: koppel's kernel, analysis and the API's sweep compiled to
# WebAssembly by Debian's emscripten (em++; its JS optimiser needs NODE_PATH=/usr/share/nodejs)
# into one JavaScript file with the module inlined (SINGLE_FILE), embedded with the page template,
# its script, uPlot and math.js into koppel_plot. Without em++ the page is not built and
# `koppel edit` says so (KOPPEL_EDITOR_PAGE=0).
find_program(KOPPEL_EMXX em++)
# checked builds (sanitizers, fuzzing) test the same sources natively: the module is built once, in
# the Release build
if(NOT KOPPEL_EMXX OR KOPPEL_SANITIZE OR KOPPEL_FUZZ)
  message(STATUS "no editor page in this build (em++ of Debian's emscripten not found, or a checked build): koppel edit will say so")
  set(KOPPEL_EDITOR_PAGE OFF CACHE INTERNAL "the editor page is built (em++ found)")
  target_compile_definitions(koppel_plot PRIVATE KOPPEL_EDITOR_PAGE=0)
  return()
endif()
target_compile_definitions(koppel_plot PRIVATE KOPPEL_EDITOR_PAGE=1)
set(KOPPEL_EDITOR_PAGE ON CACHE INTERNAL "the editor page is built (em++ found)")

# Only what a sweep, the dead centres, the ranges and ToYaml need; muparser, yaml-cpp and BTF
# have no sources here (tools/edit/wasm/absent.cpp says what stands in for them).
set(root ${CMAKE_SOURCE_DIR})
file(GLOB kernel CONFIGURE_DEPENDS ${root}/solver/kernel/src/*.cpp)
file(GLOB analysis CONFIGURE_DEPENDS ${root}/solver/analysis/src/*.cpp)
list(FILTER analysis EXCLUDE REGEX "simulation\\.cpp$")  # the equation of motion: not on the page
set(sources ${kernel} ${analysis})
foreach(s core/src/mechanism core/src/parameter_set core/src/structure core/src/transmission core/src/diagnostic
          core/src/printable_text core/src/loads core/src/build
          tools/api/src/model tools/api/src/analyses tools/api/src/display tools/api/src/sweep_layout tools/api/src/admission
          tools/api/src/editor_mechanism catalog/src/mechanism_writer catalog/src/document_splice tools/edit/wasm/module tools/edit/wasm/absent)
  list(APPEND sources ${root}/${s}.cpp)
endforeach()

# The headers em++ may see: Eigen, nlohmann/json, fmt (header-only), Boost and BTF's declarations,
# each linked into a folder of its own (all of /usr/include would bring the host's C library).
set(wasm_dir ${CMAKE_BINARY_DIR}/tools/edit/wasm)
file(MAKE_DIRECTORY ${wasm_dir}/include ${wasm_dir}/obj)
foreach(pair "Eigen=/usr/include/eigen3/Eigen" "nlohmann=/usr/include/nlohmann" "fmt=/usr/include/fmt" "boost=/usr/include/boost"
             "btf.h=${KOPPEL_SUITESPARSE_INCLUDE_DIR}/btf.h" "SuiteSparse_config.h=${KOPPEL_SUITESPARSE_INCLUDE_DIR}/SuiteSparse_config.h")
  string(REPLACE "=" ";" pair "${pair}")
  list(GET pair 0 name)
  list(GET pair 1 target)
  file(CREATE_LINK ${target} ${wasm_dir}/include/${name} SYMBOLIC)
endforeach()
set(flags -std=c++20 -O2 -fexceptions -DNDEBUG -DFMT_HEADER_ONLY -I${wasm_dir}/include)
foreach(dir core/include solver/kernel/include solver/kernel/src solver/analysis/include solver/analysis/src
            solver/synthesis/include catalog/include tools/api/include tools/api/src)
  list(APPEND flags -I${root}/${dir})
endforeach()
list(APPEND flags -I${CMAKE_BINARY_DIR}/core/include)
set(em ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs ${KOPPEL_EMXX})

# Unity units, as the native build compiles (koppel_unity_in_two): the sources of one folder in
# one unit (a folder of more than six in two), so that em++ parses Eigen a dozen times rather than
# once per source. A folder's sources are unity-safe together, as they are in its library.
set(groups "")
foreach(source IN LISTS sources)
  file(RELATIVE_PATH relative ${root} ${source})
  get_filename_component(folder ${relative} DIRECTORY)
  string(REPLACE "/" "_" group ${folder})
  if(NOT group IN_LIST groups)
    list(APPEND groups ${group})
  endif()
  list(APPEND group_${group} ${source})
endforeach()
set(objects "")
foreach(group IN LISTS groups)
  list(LENGTH group_${group} count)
  set(halves 1)
  if(count GREATER 6)
    set(halves 2)
  endif()
  math(EXPR size "(${count} + ${halves} - 1) / ${halves}")
  math(EXPR last "${halves} - 1")
  foreach(half RANGE ${last})
    math(EXPR first "${half} * ${size}")
    math(EXPR end "${first} + ${size}")
    set(unit_sources "")
    set(text "// em++ unity unit of tools/edit/edit.cmake: generated, do not edit\n")
    set(index 0)
    foreach(source IN LISTS group_${group})
      if(index GREATER_EQUAL first AND index LESS end)
        list(APPEND unit_sources ${source})
        string(APPEND text "#include \"${source}\"\n")
      endif()
      math(EXPR index "${index} + 1")
    endforeach()
    set(unit ${wasm_dir}/unity_${group}_${half}.cpp)
    file(CONFIGURE OUTPUT ${unit} CONTENT "${text}")
    set(object ${wasm_dir}/obj/unity_${group}_${half}.o)
    # em++ writes the headers it read (-MD) into a depfile, which both Ninja and Makefiles read
    add_custom_command(OUTPUT ${object} COMMAND ${em} ${flags} -MD -MF ${object}.d -c ${unit} -o ${object}
                       DEPENDS ${unit} ${unit_sources} DEPFILE ${object}.d COMMENT "em++ ${group} (unity ${half})" VERBATIM)
    list(APPEND objects ${object})
  endforeach()
endforeach()
set(module ${wasm_dir}/koppel_editor.js)
set(exports "_koppel_load,_koppel_sweep,_koppel_points,_koppel_dead_centres,_koppel_ranges,_koppel_yaml,_koppel_splice")
add_custom_command(
  OUTPUT ${module}
  COMMAND ${em} -O2 -fexceptions ${objects} -o ${module} -sMODULARIZE=1 -sEXPORT_NAME=KoppelModule -sSINGLE_FILE=1
          -sALLOW_MEMORY_GROWTH=1 -sENVIRONMENT=web -sEXPORTED_FUNCTIONS=${exports} -sEXPORTED_RUNTIME_METHODS=ccall
  DEPENDS ${objects} COMMENT "em++: the editor page's WebAssembly module" VERBATIM)
# A target of its own that depends on no library (em++ compiles the sources itself), so that the
# module is built from the first minute beside the native libraries rather than after koppel_plot's
# dependencies are linked: it is a quarter of the build's work.
add_custom_target(koppel_editor_module DEPENDS ${module})
add_dependencies(koppel_plot koppel_editor_module)

set(editor_assets ${CMAKE_BINARY_DIR}/tools/edit/editor_assets.cpp)
add_custom_command(
  OUTPUT ${editor_assets}
  COMMAND ${CMAKE_COMMAND} -D NAMES=TEMPLATE,SCRIPT,MODULE,MATHJS,MATHJS_LICENSE -D NAMESPACE=koppel::plot::editor_assets
          -D TEMPLATE=${CMAKE_CURRENT_LIST_DIR}/page.html -D SCRIPT=${CMAKE_CURRENT_LIST_DIR}/editor.js -D MODULE=${module}
          -D MATHJS=${mathjs}/lib/browser/math.js -D MATHJS_LICENSE=${mathjs}/LICENSE
          -D OUTPUT=${editor_assets} -P ${CMAKE_SOURCE_DIR}/tools/view/embed.cmake
  DEPENDS ${CMAKE_CURRENT_LIST_DIR}/page.html ${CMAKE_CURRENT_LIST_DIR}/editor.js ${module} ${CMAKE_SOURCE_DIR}/tools/view/embed.cmake
          ${npm_stamp} ${mathjs}/lib/browser/math.js ${mathjs}/LICENSE
  COMMENT "Embedding the page of koppel edit" VERBATIM)
target_sources(koppel_plot PRIVATE ${editor_assets})
# a 2 MB generated source: compiled alone, outside the unity units
set_source_files_properties(${editor_assets} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
