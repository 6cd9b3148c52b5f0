"""A mechanism's title built from its structure, for a language the file
gives no title in: "Шестиланковий важільний механізм" (six links, the frame
counted, as the textbook names them)."""

from __future__ import annotations

from typing import Any

from .errors import shown
from .i18n import Language, catalogue

__all__ = ["has_title", "sheet_title", "structure_title", "title_in", "title_warning"]


def structure_title(mechanism_or_structure: Any, lang: Language) -> str:
    """ "Шестиланковий важільний механізм" / "Six-link linkage": the number of
    links (the frame counted) and the kind, from the catalogue's [titles]."""
    structure = mechanism_or_structure
    if not hasattr(structure, "n"):
        from .structure import analyse_structure

        structure = analyse_structure(mechanism_or_structure)
    links = int(structure.n) + 1  # the moving links and the frame
    words = catalogue(lang).words("titles")
    counts = dict(words["links"])
    count = str(counts.get(str(links), str(words["links_other"]).format(n=links)))
    return str(words["linkage"]).format(count=count)


def has_title(mechanism: Any, lang: Language) -> bool:
    """True when the file gives the mechanism a title in `lang` (title, title_uk)."""
    return lang == "en" or lang in dict(getattr(mechanism, "titles", {}) or {})


def sheet_title(mechanism: Any, lang: Language) -> str:
    """The file's title in `lang`, else one built from the structure."""
    if has_title(mechanism, lang):
        return str(mechanism.title_in(lang))
    return structure_title(mechanism, lang)


def title_in(mechanism: Any, lang: Language) -> str:
    """The file's title in `lang` (`title`, `title_uk`), else one built from
    the structure: an English title is not put on a Ukrainian document (the
    note's name for sheet_title)."""
    return sheet_title(mechanism, lang)


def title_warning(mechanism: Any, lang: Language) -> str | None:
    """The warning where the title in `lang` is built from the structure."""
    if has_title(mechanism, lang):
        return None
    words = catalogue(lang).words("titles")
    return str(words["no_title"]).format(
        file=shown(mechanism.path), lang=lang, title=structure_title(mechanism, lang)
    )
