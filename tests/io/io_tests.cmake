math(EXPR _timeout_300s "300 * ${FPMSHELL_TIMEOUT_SCALE}")
add_test(NAME io.command_line
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/cli_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/io_test_work)
set_tests_properties(io.command_line PROPERTIES LABELS io TIMEOUT ${_timeout_300s})

# The VTU frames loaded by VTK's own reader (python3-vtk9): an implementation independent of ours.
add_test(NAME io.vtu_reader
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/vtu_reader_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/vtu_reader_test_work)
set_tests_properties(io.vtu_reader PROPERTIES LABELS io TIMEOUT ${_timeout_300s})

# LS-DYNA keyword decks run as they are: each test deck of examples/decks against its YAML twin,
# The test decks against their YAML twins, `fpmshell convert` and `check` (tests/io/deck_test.py).
add_test(NAME io.lsdyna_decks
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/deck_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/deck_test_work)
set_tests_properties(io.lsdyna_decks PROPERTIES LABELS io TIMEOUT ${_timeout_300s})

# Refused, noted and misread cards of small decks, each one sentence naming file, line and card
# (tests/io/deck_messages_test.py).
add_test(NAME io.lsdyna_deck_messages
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/deck_messages_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/deck_messages_test_work)
set_tests_properties(io.lsdyna_deck_messages PROPERTIES LABELS io TIMEOUT ${_timeout_300s})

# Card order is free: every test deck with its cards reversed, shuffled and spread over nested
# *INCLUDE files gives the same model and history.csv bytes (tests/io/deck_order_test.py).
add_test(NAME io.deck_card_order
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/deck_order_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/deck_order_test_work)
set_tests_properties(io.deck_card_order PROPERTIES LABELS io TIMEOUT ${_timeout_300s})

# The air blast of decks (*LOAD_BLAST_ENHANCED, *LOAD_BLAST_SEGMENT(_SET)): variants of
# examples/decks/blast_panel against it and their twins, and their refusals
# (tests/io/deck_blast_test.py).
add_test(NAME io.deck_blast
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/deck_blast_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/deck_blast_test_work)
set_tests_properties(io.deck_blast PROPERTIES LABELS io TIMEOUT ${_timeout_300s})

# The rules through the thickness of decks: NIP (Gauss), *CONTROL_SHELL INTGRD (Lobatto),
# *INTEGRATION_SHELL (user rules) against YAML twins, and their refusals
# (tests/io/deck_rules_test.py).
add_test(NAME io.deck_thickness_rules
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/deck_rules_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/deck_rules_test_work)
set_tests_properties(io.deck_thickness_rules PROPERTIES LABELS io TIMEOUT ${_timeout_300s})

# The rigid-body cards of decks (*BOUNDARY_PRESCRIBED_MOTION_RIGID, ...) against YAML twins, and
# their refusals (tests/io/deck_rigid_test.py).
add_test(NAME io.deck_rigid_bodies
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/deck_rigid_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/deck_rigid_test_work)
set_tests_properties(io.deck_rigid_bodies PROPERTIES LABELS io TIMEOUT ${_timeout_300s})

# Point masses of decks (*ELEMENT_MASS, _NODE_SET) against a YAML twin, and their refusals
# (tests/io/deck_mass_test.py).
add_test(NAME io.deck_point_masses
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/deck_mass_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/deck_mass_test_work)
set_tests_properties(io.deck_point_masses PROPERTIES LABELS io TIMEOUT ${_timeout_300s})
# Material cards of decks (*MAT_098, *MAT_123, LCSR) against the YAML twins
# (tests/io/deck_material_test.py).
add_test(NAME io.deck_material_cards
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/deck_material_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/deck_material_test_work)
set_tests_properties(io.deck_material_cards PROPERTIES LABELS io TIMEOUT ${_timeout_300s})

# Gravity of decks: *LOAD_BODY_X, _Y, _Z and *LOAD_BODY_PARTS against the YAML twin
# (tests/io/deck_gravity_test.py).
add_test(NAME io.deck_gravity
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/deck_gravity_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/deck_gravity_test_work)
set_tests_properties(io.deck_gravity PROPERTIES LABELS io TIMEOUT ${_timeout_300s})

# Rigid parts of solids and *PART_INERTIA in decks against YAML twins, the two-card form of
# *ELEMENT_SOLID, and their refusals (tests/io/deck_solid_test.py).
add_test(NAME io.deck_rigid_solids
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/deck_solid_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/deck_solid_test_work)
set_tests_properties(io.deck_rigid_solids PROPERTIES LABELS io TIMEOUT ${_timeout_300s})

# The README is true: every command it shows runs and prints what it says, its model is the
# example's file, its links and pictures exist (tests/io/readme_test.py).
add_test(NAME io.readme
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/readme_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/readme_test_work)
set_tests_properties(io.readme PROPERTIES LABELS io TIMEOUT ${_timeout_300s})
