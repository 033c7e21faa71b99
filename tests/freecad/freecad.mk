# FreeCAD workbench tests, run by the top-level `make check-freecad`:
#   make -f tests/freecad/freecad.mk BUILD=build
# - every tests/freecad/test_*.py as `freecadcmd -t <module>` runs it, in FC_GROUPS processes
#   (tests/freecad/fc_group.py; each module's unittest summary in its own
#   log is checked, and the group's exit code: freecadcmd alone exits 0 on a failing script);
# - the GUI smoke test (tests/freecad/gui_smoke.py) in `freecad` under `xvfb-run -a`,
#   on the demo document examples/demo.py makes headless first ($(BUILD)/freecad/demo/);
#   it keeps its screenshots ($(BUILD)/freecad/gui_*.png) and a result file checked here.
# FreeCAD runs with HOME=$(BUILD)/freecad/home, whose Mod folder links to freecad_wb/,
# so the user's real ~/.local and ~/.config are never touched, and with TMPDIR in it: the
# Start page leaves a FreeCADStartThumbnails folder in the temporary directory at each
# GUI start (and the single-instance socket, `FreeCAD`, stays there too).
# The GUI smoke (and the demo document it opens) has a HOME of its own, made the same way
# ($(BUILD)/freecad/gui-home): FreeCAD writes its configuration into HOME when it quits, so
# with one HOME each its tests and the smoke can run side by side (make -j: make check runs
# them as two jobs, neither waiting for the other's ~3 min).
BUILD     ?= build
FCDIR     := $(BUILD)/freecad
FCHOME    := $(CURDIR)/$(FCDIR)/home
GUIHOME   := $(CURDIR)/$(FCDIR)/gui-home
FC_TESTS  := $(basename $(notdir $(wildcard tests/freecad/test_*.py)))
# $(call fc-env,HOME): the environment FreeCAD runs in
fc-env     = HOME=$(1) LIBELASTICA_PATH=$(CURDIR)/$(BUILD)/libelastica.so \
             PYTHONPATH=$(CURDIR)/python:$(CURDIR)/tests/freecad \
             QTWEBENGINE_DISABLE_SANDBOX=1 ELASTICA_TEST_OUT=$(CURDIR)/$(FCDIR) TMPDIR=$(1)/tmp
FC_ENV     = $(call fc-env,$(FCHOME))
GUI_ENV    = $(call fc-env,$(GUIHOME))
# a hang guard, not a timing test: test_elastica_fit takes ~92 s alone and 130-160 s at load 13-15
# on 2 cores (fcnums, 21:27): 150 s failed it under load; 400 s still stops a hang
TIMEOUT   ?= 400
# the GUI smoke drives every panel (467 checks at 4b4c3af; its waits poll, gui_smoke.wait): ~3 min at load 12 on 2 cores
GUI_TIMEOUT ?= 450

.PHONY: all fc-home fc-gui-home fc-tests fc-gui fc-demo fc-gallery fc-addon
all: fc-tests fc-gui fc-addon

# $(call fresh-home,HOME): a fresh HOME without a Mod folder: `make freecad-install` must
# make it and link the workbench
define fresh-home
	@rm -rf $(1) && mkdir -p $(1)/tmp
	+@$(MAKE) --no-print-directory -f Makefile freecad-install FREECAD_MOD=$(1)/.local/share/FreeCAD/Mod \
	  BUILD=$(BUILD) > /dev/null
	@test "$$(readlink $(1)/.local/share/FreeCAD/Mod/elastica)" = "$(CURDIR)/freecad_wb" || \
	  { echo "FAILED: make freecad-install did not link $(1)/.local/share/FreeCAD/Mod/elastica"; exit 1; }
endef
fc-home:
	$(call fresh-home,$(FCHOME))
fc-gui-home:
	$(call fresh-home,$(GUIHOME))

# The modules run in FC_GROUPS freecadcmd processes (fc_group.py: modules i, i + FC_GROUPS, ...),
# not one each: a FreeCAD start-up with the workbench imported costs ~1 s of CPU, 73 times
# (the first nine modules: 27.9 CPU-s one process each, 20.1 in one). Each module keeps its
# log ($(FCDIR)/<module>.log, checked as before: its unittest summary), its documents (every
# document closed between modules) and its hang guard (TIMEOUT s: the process ends with the
# module's traceback in its log); GROUP_TIMEOUT stops a group that hangs between modules.
FC_GROUPS ?= 4
GROUP_TIMEOUT ?= 1500
fc-tests: fc-home
	@set -e; mods="$(FC_TESTS)"; n=$$(echo $$mods | wc -w); \
	for g in $$(seq 0 $$(($(FC_GROUPS) - 1))); do \
	  grp=$$(echo $$mods | tr ' ' '\n' | awk -v g=$$g -v n=$(FC_GROUPS) 'NR % n == g' | tr '\n' ' '); \
	  [ -n "$$grp" ] || continue; \
	  for m in $$grp; do rm -f $(FCDIR)/$$m.log; done; \
	  echo "== freecadcmd tests/freecad/fc_group.py: group $$((g + 1)) of $(FC_GROUPS), $$(echo $$grp | wc -w) of $$n modules"; \
	  rc=0; env $(FC_ENV) FC_GROUP="$$grp" FC_GROUP_LOGS=$(CURDIR)/$(FCDIR) FC_MODULE_TIMEOUT=$(TIMEOUT) \
	    timeout $(GROUP_TIMEOUT) freecadcmd $(CURDIR)/tests/freecad/fc_group.py > $(FCDIR)/group-$$g.log 2>&1 || rc=$$?; \
	  for m in $$grp; do log=$(FCDIR)/$$m.log; echo "== freecadcmd -t $$m"; \
	    if [ ! -f $$log ]; then tail -n 30 $(FCDIR)/group-$$g.log; \
	      echo "FAILED: freecadcmd -t $$m not run: its group ended before it (exit $$rc, log $(FCDIR)/group-$$g.log)"; exit 1; fi; \
	    if ! grep -q '^OK' $$log || ! grep -Eq '^Ran [1-9][0-9]* test' $$log; then \
	      if grep -q '^=\{10,\}' $$log; then sed -n '/^=\{10,\}/,$$p' $$log | tail -n 80; else tail -n 80 $$log; fi; \
	      echo "FAILED: freecadcmd -t $$m (group exit $$rc, log $$log)"; exit 1; fi; \
	    grep -E '^Ran [0-9]+ test' $$log; \
	  done; \
	  if [ $$rc -ne 0 ]; then tail -n 30 $(FCDIR)/group-$$g.log; \
	    echo "FAILED: freecadcmd tests/freecad/fc_group.py group $$((g + 1)) (exit $$rc, log $(FCDIR)/group-$$g.log)"; exit 1; fi; \
	done

# an Addon Manager install: the repository itself in Mod/ (its package.xml puts freecad_wb/
# on sys.path, the C sources' libelastica/ folder must not pass for the Python package)
ADDON_HOME := $(CURDIR)/$(FCDIR)/addon-home
fc-addon:
	@echo "== freecadcmd: the workbench installed as an addon (repository in Mod/)"
	@rm -rf $(ADDON_HOME) && mkdir -p $(ADDON_HOME)/.local/share/FreeCAD/Mod
	@ln -s $(CURDIR) $(ADDON_HOME)/.local/share/FreeCAD/Mod/Elastica
	@out=$$(HOME=$(ADDON_HOME) LIBELASTICA_PATH=$(CURDIR)/$(BUILD)/libelastica.so timeout $(TIMEOUT) \
	  freecadcmd -c "import freecad.elastica as e; p = e.library_problem(); import libelastica as el; \
	print('ADDON', p or 'OK', el.__file__)" 2>&1 | grep '^ADDON'); \
	case "$$out" in "ADDON OK $(CURDIR)/python/libelastica/__init__.py") echo "$$out";; \
	  *) echo "FAILED: addon install: $$out"; exit 1;; esac

fc-demo: fc-gui-home
	@rc=0; env $(GUI_ENV) ELASTICA_DEMO_OUT=$(CURDIR)/$(FCDIR)/demo timeout $(TIMEOUT) \
	  freecadcmd $(CURDIR)/examples/demo.py > $(FCDIR)/demo.log 2>&1 || rc=$$?; \
	if [ $$rc -ne 0 ]; then tail -n 30 $(FCDIR)/demo.log; echo "FAILED: the demo document"; exit 1; fi

fc-gui: fc-gui-home fc-demo
	@echo "== freecad (GUI, xvfb-run -a) tests/freecad/gui_smoke.py"
	@rm -f $(FCDIR)/gui_smoke.result $(FCDIR)/gui_*.png
	@rc=0; env $(GUI_ENV) timeout $(GUI_TIMEOUT) xvfb-run -a -s "-screen 0 1280x1024x24" \
	  freecad $(CURDIR)/tests/freecad/gui_smoke.py > $(FCDIR)/gui_smoke.log 2>&1 || rc=$$?; \
	if [ $$rc -ne 0 ] || [ "$$(head -n 1 $(FCDIR)/gui_smoke.result 2>/dev/null)" != "PASS" ]; then \
	  tail -n 40 $(FCDIR)/gui_smoke.log; cat $(FCDIR)/gui_smoke.result 2>/dev/null; \
	  echo "FAILED: GUI smoke test (exit $$rc, log $(FCDIR)/gui_smoke.log)"; exit 1; fi
	@tail -n +2 $(FCDIR)/gui_smoke.result

# the README's screenshot of the workbench (make gallery): the demo document in FreeCAD
fc-gallery: fc-gui-home fc-demo
	@rc=0; env $(GUI_ENV) ELASTICA_GALLERY=$(CURDIR)/docs/gallery timeout $(TIMEOUT) \
	  xvfb-run -a -s "-screen 0 1280x1024x24" freecad $(CURDIR)/tests/freecad/gallery.py \
	  > $(FCDIR)/gallery.log 2>&1 || rc=$$?; \
	if [ $$rc -ne 0 ]; then tail -n 30 $(FCDIR)/gallery.log; echo "FAILED: the FreeCAD screenshot"; exit 1; fi
	@echo "docs/gallery/freecad_workbench.png"
