# Unity builds: each target's sources are compiled 16 to a translation unit, so the headers they
# share (Eigen, GoogleTest, Cyclone DDS, nlohmann-json, Boost.Beast) are parsed once per batch
# instead of once per file; a cold build takes about half the time on two cores. Configure with
# -DCMAKE_UNITY_BUILD=OFF for one unit per file (quicker rebuilds while editing a single file).
# pool_unity_alone() lists the files that keep a unit of their own: their file-local names
# (anonymous namespaces) clash with a sibling's, or a member's type is file-local (g++'s
# -Wsubobject-linkage).
if(NOT DEFINED CMAKE_UNITY_BUILD)
  set(CMAKE_UNITY_BUILD ON)
endif()
if(NOT DEFINED CMAKE_UNITY_BUILD_BATCH_SIZE)
  set(CMAKE_UNITY_BUILD_BATCH_SIZE 16)
endif()

# pool_unity_alone(DIR FILE...): FILEs (relative to the source tree) of targets made in DIR.
function(pool_unity_alone dir)
  list(TRANSFORM ARGN PREPEND ${PROJECT_SOURCE_DIR}/)
  set_source_files_properties(${ARGN} DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}
    PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
endfunction()

# The test files that keep a unit of their own (pool_unity_skips applies it; pool_test_module counts
# them to tell how many units a test module compiles to).
set(POOL_UNITY_ALONE_TESTS tests/net/command_signature_test.cpp tests/physics/break_test.cpp
  tests/physics/cushion_mathavan_test.cpp tests/physics/cushion_stronge_test.cpp
  tests/physics/cushion_test.cpp tests/physics/jump_masse_test.cpp
  tests/physics/pocket_test.cpp tests/rules/log_check_test.cpp tests/rules/rotation_test.cpp
  tests/scenario/sim_absurd_input_test.cpp tests/server/match_registry_test.cpp
  tests/server/match_test.cpp tests/render/cue_pose_test.cpp tests/render/cue_shadow_test.cpp
  tests/render/render_hall_test.cpp tests/render/render_light_test.cpp
  tests/render/render_screenshot_test.cpp tests/audio/sound_board_test.cpp)

# pool_unity_units(OUT SOURCES...): how many translation units SOURCES (absolute paths) compile to.
function(pool_unity_units out)
  set(alone 0)
  foreach(source ${ARGN})
    file(RELATIVE_PATH relative ${PROJECT_SOURCE_DIR} ${source})
    if(relative IN_LIST POOL_UNITY_ALONE_TESTS)
      math(EXPR alone "${alone} + 1")
    endif()
  endforeach()
  list(LENGTH ARGN count)
  if(CMAKE_UNITY_BUILD)
    math(EXPR units
      "(${count} - ${alone} + ${CMAKE_UNITY_BUILD_BATCH_SIZE} - 1) / ${CMAKE_UNITY_BUILD_BATCH_SIZE} + ${alone}")
  else()
    set(units ${count})
  endif()
  set(${out} ${units} PARENT_SCOPE)
endfunction()

function(pool_unity_skips)
  pool_unity_alone(common/net common/net/client_transport.cpp common/net/server_transport.cpp)
  pool_unity_alone(common/physics common/physics/events.cpp common/physics/pocket_world.cpp)
  pool_unity_alone(common/protocol common/protocol/server_signature.cpp)
  pool_unity_alone(common/rules common/rules/rotation.cpp)
  pool_unity_alone(common/scenario common/scenario/scenario_write.cpp)
  pool_unity_alone(server/match server/match/match_practice.cpp)
  pool_unity_alone(client client/render/cue_shadow.cpp client/ui/scene_convert.cpp)
  if(POOL_BUILD_TESTS)
    pool_unity_alone(tests ${POOL_UNITY_ALONE_TESTS})
  endif()
endfunction()
