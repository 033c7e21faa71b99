"""The document observer of an Elastica task panel (panelbase.Panel): ``Watch`` closes the
panel whose feature or transaction goes (deleted, undone, redone, its document closed),
follows a recompute that is not the panel's, and counts the pieces of its transaction
another command commits."""
from __future__ import annotations

from PySide import QtCore


class Watch:
    """A document observer that closes a panel whose feature leaves its document (Undo
    of the command that made it, a deletion in the tree): the panel stayed open on a
    feature that was gone, and its OK reported success with nothing kept. And one whose
    document is undone or redone while it is open (Edit > Undo is active during a task
    dialog in FreeCAD 0.20, whatever the dialog says): the undo takes the panel's open
    transaction with it (its edits, or the step before when it had none), so the panel
    stayed open on values the document no longer had, its later edits outside any
    transaction, and Cancel could revert none of them. The panel closes then, the
    document as the undo left it, as FreeCAD's own edits end when their transaction
    goes."""

    def __init__(self, panel):
        self.panel = panel

    def mine(self, doc):
        try:
            return doc.Name == self.panel.doc_name
        except Exception:  # a document half torn down: not ours to judge
            return False

    def slotDeletedObject(self, obj):
        p = self.panel
        try:
            mine = obj.Document.Name == p.doc_name and obj.Name == p.name
        except Exception:  # an object half torn down: not ours to judge
            mine = False
        if mine:
            p.lost("undone or deleted")

    def slotUndoDocument(self, doc):
        if self.mine(doc):
            self.panel.lost("Undo took its edit back")

    def slotRedoDocument(self, doc):
        if self.mine(doc):
            self.panel.lost("Redo replaced its edit")

    def slotDeletedDocument(self, doc):
        # File > Close (its GUI document gone, FreeCAD's unsetEdit closed a panel in edit
        # mode): the panel stayed on the Start page, its OK and Cancel on a deleted document
        if self.mine(doc):
            self.panel.lost("its document closed")

    def slotRecomputedDocument(self, doc):
        # a recompute not the panel's (a cell its feature is bound to changed): it follows
        if self.mine(doc):
            QtCore.QTimer.singleShot(0, self.panel.follow_recompute)

    def slotCommitTransaction(self, doc):
        # a command run while the panel is open commits every pending transaction as it
        # opens its own (Std_Delete: App::Application::setActiveTransaction)
        if self.mine(doc):
            self.panel.committed_by_other()
