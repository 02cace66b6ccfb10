# Debian packages through CPack: pool-common (assets, docs), pool-server (the server as a service),
# pool-client (the game window, the bot, the physics lab and tools). `cpack -G DEB` in a build.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME pool)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "pool maintainers <pool@localhost>")
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR}/packages)
# The programs are stripped, their debug information split into -dbgsym packages (.ddeb) beside
# them, as Debian's own packages do (CPack strips what it splits: no CPACK_STRIP_FILES, which
# would strip first and leave nothing to split).
set(CPACK_DEBIAN_SERVER_DEBUGINFO_PACKAGE ON)
set(CPACK_DEBIAN_CLIENT_DEBUGINFO_PACKAGE ON)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL common server client)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_PACKAGE_SECTION games)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# Library dependencies come from the programs themselves (dpkg-shlibdeps), so they name the
# Debian 12 packages the binaries were linked against.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
# Each package depends on exactly this version of the shared data. A component's description's
# first line is its package's summary.
set(pool_common_dep "pool-common (= ${PROJECT_VERSION}-${CPACK_DEBIAN_PACKAGE_RELEASE})")

set(CPACK_DEBIAN_COMMON_PACKAGE_NAME pool-common)
set(CPACK_DEBIAN_COMMON_PACKAGE_ARCHITECTURE all)
set(CPACK_COMPONENT_COMMON_DESCRIPTION
  "3D pool (billiards) game for the LAN: shared data\nTable specs and meshes, shot scenes, DDS configurations and the documentation\nof the pool game, its server and its physics lab.")

set(CPACK_DEBIAN_SERVER_PACKAGE_NAME pool-server)
set(CPACK_DEBIAN_SERVER_PACKAGE_DEPENDS "${pool_common_dep}")
set(CPACK_COMPONENT_SERVER_DESCRIPTION
  "3D pool (billiards) game for the LAN: match server\npool-server runs many 8-ball matches over Cyclone DDS, with physics on ODE and\nevery match kept in SQLite. Ships a systemd unit (pool-server.service, not\nenabled on install) with its settings in /etc/pool/pool-server.conf and its\ndatabase in /var/lib/pool.")
set(CPACK_DEBIAN_SERVER_PACKAGE_CONTROL_EXTRA
  "${CMAKE_CURRENT_LIST_DIR}/deb/server/conffiles;${CMAKE_CURRENT_LIST_DIR}/deb/server/postinst;${CMAKE_CURRENT_LIST_DIR}/deb/server/prerm;${CMAKE_CURRENT_LIST_DIR}/deb/server/postrm")

set(CPACK_DEBIAN_CLIENT_PACKAGE_NAME pool-client)
# The HUD's font is read from fonts-dejavu-core; Mesa's drivers draw where no other GL is present.
set(CPACK_DEBIAN_CLIENT_PACKAGE_DEPENDS "${pool_common_dep}, fonts-dejavu-core")
set(CPACK_DEBIAN_CLIENT_PACKAGE_RECOMMENDS "libgl1-mesa-dri")
set(CPACK_COMPONENT_CLIENT_DESCRIPTION
  "3D pool (billiards) game for the LAN: game window, bot and physics lab\npool-client is the game window (OpenGL 3.3): lobby, play and watch matches of a\npool-server on the LAN. Also pool-web (the web spectator: any browser on the\nLAN watches the matches; the page and three.js in /usr/share/pool/web),\npool-bot (a headless player), pool-sim (one shot offline, JSON out),\npool-sound and pool-tablegen.")

include(CPack)
