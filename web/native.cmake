# The WebAssembly build seen from the native build (docs/web.md): the target `scantrace_web`
# configures and builds web/ with emscripten's toolchain into ${CMAKE_BINARY_DIR}/web (build/web/:
# the ES module, its .wasm, the JavaScript API and the explorer page), and the tests that hold the
# module to the native command run in this build's ctest. Included by the top-level
# CMakeLists.txt when SCANTRACE_BUILD_WEB is on.
find_program(SCANTRACE_EMCC emcc)
find_program(SCANTRACE_NODE node)
set(SCANTRACE_EMSCRIPTEN_TOOLCHAIN /usr/share/emscripten/cmake/Modules/Platform/Emscripten.cmake
    CACHE FILEPATH "emscripten's CMake toolchain file (Debian's emscripten package)")
if(NOT SCANTRACE_EMCC OR NOT SCANTRACE_NODE OR NOT EXISTS ${SCANTRACE_EMSCRIPTEN_TOOLCHAIN})
  message(WARNING "SCANTRACE_BUILD_WEB: emcc, node or ${SCANTRACE_EMSCRIPTEN_TOOLCHAIN} not "
                  "found (bash scripts/deps.sh installs emscripten and nodejs); the web build and "
                  "its tests are left out")
  return()
endif()

# Debian's emscripten runs its JavaScript tools with `node` and Debian's node-acorn, which a Node
# from elsewhere (NodeSource's) does not look for in /usr/share/nodejs.
set(web_env NODE_PATH=/usr/share/nodejs)
set(web_dir ${CMAKE_BINARY_DIR}/web)
# Its own make, which does not share the outer one's job slots: as many jobs as cores.
cmake_host_system_information(RESULT web_jobs QUERY NUMBER_OF_LOGICAL_CORES)
# Two builds (web/CMakeLists.txt says why): the explorer's, then the trace page's, which writes
# its module and page into the explorer's folder. The same settings as the presets `web` and
# `web-player` (CMakePresets.json), which scripts/build.sh --web uses.
add_custom_target(scantrace_web ALL
  COMMAND ${CMAKE_COMMAND} -E env ${web_env} ${CMAKE_COMMAND} -S ${PROJECT_SOURCE_DIR} -B ${web_dir}
          -DCMAKE_TOOLCHAIN_FILE=${SCANTRACE_EMSCRIPTEN_TOOLCHAIN} -DCMAKE_BUILD_TYPE=Release
          -G "Unix Makefiles" --log-level=WARNING
  COMMAND ${CMAKE_COMMAND} -E env ${web_env} ${CMAKE_COMMAND} --build ${web_dir} --parallel ${web_jobs}
  COMMAND ${CMAKE_COMMAND} -E env ${web_env} ${CMAKE_COMMAND} -S ${PROJECT_SOURCE_DIR}
          -B ${web_dir}-player -DCMAKE_TOOLCHAIN_FILE=${SCANTRACE_EMSCRIPTEN_TOOLCHAIN}
          -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-Oz -DNDEBUG"
          -DSCANTRACE_WEB_PLAYER_BUILD=ON -DSCANTRACE_WEB_OUTPUT_DIR=${web_dir}
          -G "Unix Makefiles" --log-level=WARNING
  COMMAND ${CMAKE_COMMAND} -E env ${web_env} ${CMAKE_COMMAND} --build ${web_dir}-player
          --target scantrace_player_page --parallel ${web_jobs}
  COMMENT "WebAssembly builds (emscripten) into ${web_dir} and ${web_dir}-player"
  USES_TERMINAL)

if(SCANTRACE_BUILD_TESTS)
  # The web build's configuration alone, in a folder of its own: it fails when a library folder's
  # .cpp is in none of that folder's targets there and needs no capability that is off there
  # (scantrace_check_library_sources, cmake/scantrace_capabilities.cmake).
  add_test(NAME "web: every library source is built for the web or refused by a named option"
           COMMAND ${CMAKE_COMMAND} -E env ${web_env} ${CMAKE_COMMAND} -S ${PROJECT_SOURCE_DIR}
                   -B ${CMAKE_BINARY_DIR}/web-tests/configure
                   -DCMAKE_TOOLCHAIN_FILE=${SCANTRACE_EMSCRIPTEN_TOOLCHAIN}
                   -DCMAKE_BUILD_TYPE=Release -G "Unix Makefiles" --log-level=WARNING)
  set_tests_properties("web: every library source is built for the web or refused by a named option"
                       PROPERTIES LABELS "web" TIMEOUT 300)
  # Each of the two WebAssembly builds compiles each file once (web/CMakeLists.txt), read from
  # their compile_commands.json (web/tests/node_compile_once.mjs).
  add_test(NAME "web: each WebAssembly build compiles each file once"
           COMMAND ${SCANTRACE_NODE} ${PROJECT_SOURCE_DIR}/web/tests/node_compile_once.mjs
                   ${web_dir} ${web_dir}-player)
  set_tests_properties("web: each WebAssembly build compiles each file once"
                       PROPERTIES LABELS "web" TIMEOUT 60)
  # A Node test of the module against the native command (its binary, a work folder and the demo
  # scene as arguments).
  function(add_node_command_test name script timeout)
    add_test(NAME "${name}"
             COMMAND ${SCANTRACE_NODE} ${PROJECT_SOURCE_DIR}/web/tests/${script}.mjs ${web_dir}
                     $<TARGET_FILE:scantrace> ${CMAKE_BINARY_DIR}/web-tests/${ARGN}
                     ${CMAKE_BINARY_DIR}/examples/demo/demo_scene.json)
    set_tests_properties("${name}" PROPERTIES FIXTURES_REQUIRED demo_files LABELS "web"
                         TIMEOUT ${timeout})
  endfunction()
  # The module against the native command: pixels, traces, why and diff (web/tests/node_compare.mjs).
  add_node_command_test("web: node module equals the native command" node_compare 600 node)
  # The API checks its arguments as the command does, caps a trace's text, and pre-checks an
  # image against the scene's canvas (web/tests/node_arguments.mjs).
  add_node_command_test("web: node API checks its arguments as the command does" node_arguments
                        300 arguments)
  # The API's option names: optionTable()'s are the command's, and the module and the explorer's
  # address take exactly them (web/tests/node_options.mjs).
  add_node_command_test("web: node API takes exactly the option tables' names" node_options 120
                        options)
  # The trace page's module against the full one: its exports, its steps and frames
  # (web/tests/node_player.mjs).
  add_test(NAME "web: node player module composes the full module's frames"
           COMMAND ${SCANTRACE_NODE} ${PROJECT_SOURCE_DIR}/web/tests/node_player.mjs ${web_dir})
  set_tests_properties("web: node player module composes the full module's frames" PROPERTIES
                       LABELS "web" TIMEOUT 300)
  # The explorer's answers in the command's words (web/tests/node_answers.mjs; plain JavaScript:
  # no module needed).
  add_test(NAME "web: explorer answers in the command's words"
           COMMAND ${SCANTRACE_NODE} ${PROJECT_SOURCE_DIR}/web/tests/node_answers.mjs)
  set_tests_properties("web: explorer answers in the command's words" PROPERTIES
                       LABELS "web" TIMEOUT 60)
endif()

if(SCANTRACE_BUILD_TESTS)
  # The explorer page in headless Chromium, opened from file:// (web/tests/chromium_explorer.mjs).
  # `scantrace explore -o` writes the page the Chromium test opens, into a folder made here: the
  # command, like every output of scantrace, does not create missing parent folders (a fresh
  # clone's CI failed on it where a worktree had the folder from an earlier run).
  file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/web-tests)
  add_test(NAME "web: scantrace explore writes the explorer page"
           COMMAND $<TARGET_FILE:scantrace> explore -o ${CMAKE_BINARY_DIR}/web-tests/explorer.html)
  set_tests_properties("web: scantrace explore writes the explorer page" PROPERTIES
                       LABELS "web" FIXTURES_SETUP explorer_page)
  find_program(SCANTRACE_CHROMIUM chromium)
  if(SCANTRACE_CHROMIUM)
    add_test(NAME "web: explorer in headless Chromium"
             COMMAND ${SCANTRACE_NODE} --experimental-websocket --no-warnings
                     ${PROJECT_SOURCE_DIR}/web/tests/chromium_explorer.mjs
                     ${CMAKE_BINARY_DIR}/web-tests/explorer.html
                     $<TARGET_FILE:scantrace> ${CMAKE_BINARY_DIR}/web-tests/chromium)
    set_tests_properties("web: explorer in headless Chromium" PROPERTIES LABELS "web;browser"
                         FIXTURES_REQUIRED explorer_page TIMEOUT 300)
    # At a projector's, a desktop's and a phone's sizes, screenshots kept in
    # web-tests/chromium-sizes/screenshots/ (web/tests/chromium_explorer_sizes.mjs).
    add_test(NAME "web: explorer at lecture sizes in headless Chromium"
             COMMAND ${SCANTRACE_NODE} --experimental-websocket --no-warnings
                     ${PROJECT_SOURCE_DIR}/web/tests/chromium_explorer_sizes.mjs
                     ${CMAKE_BINARY_DIR}/web-tests/explorer.html
                     ${CMAKE_BINARY_DIR}/web-tests/chromium-sizes)
    set_tests_properties("web: explorer at lecture sizes in headless Chromium" PROPERTIES
                         LABELS "web;browser" FIXTURES_REQUIRED explorer_page TIMEOUT 300)
  endif()
endif()

if(SCANTRACE_BUILD_TESTS AND SCANTRACE_CHROMIUM)
  # The trace page of `replay -o OUT.html` in headless Chromium (web/tests/chromium_trace_page.mjs).
  add_test(NAME "web: trace page in headless Chromium"
           COMMAND ${SCANTRACE_NODE} --experimental-websocket --no-warnings
                   ${PROJECT_SOURCE_DIR}/web/tests/chromium_trace_page.mjs $<TARGET_FILE:scantrace>
                   ${CMAKE_BINARY_DIR}/web-tests/trace_page ${web_dir})
  set_tests_properties("web: trace page in headless Chromium" PROPERTIES LABELS "web;browser"
                       TIMEOUT 300)
  # The trace page at lecture and phone sizes, its screenshots kept in
  # web-tests/trace-page-sizes/screenshots/ (web/tests/chromium_trace_page_sizes.mjs).
  add_test(NAME "web: trace page at lecture sizes in headless Chromium"
           COMMAND ${SCANTRACE_NODE} --experimental-websocket --no-warnings
                   ${PROJECT_SOURCE_DIR}/web/tests/chromium_trace_page_sizes.mjs $<TARGET_FILE:scantrace>
                   ${CMAKE_BINARY_DIR}/web-tests/trace-page-sizes ${web_dir})
  set_tests_properties("web: trace page at lecture sizes in headless Chromium" PROPERTIES
                       LABELS "web;browser" TIMEOUT 300)
endif()
