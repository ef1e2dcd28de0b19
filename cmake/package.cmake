# CPack: `cpack -G DEB` in the build directory makes clpost_<version>_<arch>.deb from the install
# rules (prefix /usr). The run-time dependencies are worked out by dpkg-shlibdeps (package
# dpkg-dev) from the libraries the binary links, so they follow the Debian release it is built on
# (Debian 12: libfmt9, libyaml-cpp0.7, libstdc++6, libgcc-s1, libc6).
# tests/packaging/deb_test.sh builds the package, unpacks it and posts a sample with it.
set(CPACK_PACKAGE_NAME clpost)
set(CPACK_PACKAGE_VENDOR "clpost")
set(CPACK_PACKAGE_CONTACT "clpost developers <dev@clpost.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "APT/CL to NC post-processor for CNC lathes, built for threading")
# The long description: lines of at most 80 columns (CPack indents each one for the control file).
string(JOIN "\n" CPACK_PACKAGE_DESCRIPTION
  "clpost turns the cutter-location (APT/CL) files of CAM systems into NC"
  "programs for CNC lathes. Machines are YAML files; seven are shipped: ISO,"
  "LinuxCNC, SINUMERIK 840D, Fanuc 0i-T, Haas ST, HEIDENHAIN CNC PILOT and"
  "NCT 2000T. Threads are planned pass by pass: a control's threading cycle"
  "is written only when the passes it cuts equal the plan, and clpost verify"
  "reads a program back through the control's laws to prove it.")
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${CPACK_PACKAGE_CONTACT}")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SUGGESTS bash-completion)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

include(CPack)
