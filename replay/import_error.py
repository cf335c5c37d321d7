"""The one error an import stops with: tessref import prints it and exits 2, leaving no output."""


class ImportFailure(Exception):
    pass
