"""A mechanism's title in a language the file gives no title in, built from
its structure: "Шестиланковий важільний механізм" ("six-link linkage"), as
seed 002 names its tasks by the number of links and the kind of mechanism.

    >>> import mmt_plans
    >>> m = mmt_plans.load("samples/six_link_press.toml")
    >>> structure_title(m, "uk")
    'Шестиланковий важільний механізм'
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from .model import Mechanism

__all__ = ["structure_title", "title_in", "title_warning"]

# the number of links, the frame included → the word that counts them
_UK = {
    2: "Дволанковий",
    3: "Триланковий",
    4: "Чотириланковий",
    5: "П'ятиланковий",
    6: "Шестиланковий",
    7: "Семиланковий",
    8: "Восьмиланковий",
    9: "Дев'ятиланковий",
    10: "Десятиланковий",
    11: "Одинадцятиланковий",
    12: "Дванадцятиланковий",
    13: "Тринадцятиланковий",
    14: "Чотирнадцятиланковий",
}
_EN = {
    2: "Two",
    3: "Three",
    4: "Four",
    5: "Five",
    6: "Six",
    7: "Seven",
    8: "Eight",
    9: "Nine",
    10: "Ten",
    11: "Eleven",
    12: "Twelve",
    13: "Thirteen",
    14: "Fourteen",
}


def structure_title(mechanism: Mechanism, lang: str) -> str:
    """ "Шестиланковий важільний механізм" / "Six-link linkage": the number of
    links (the frame counted, as seed 002 counts them) and the kind."""
    n = len(mechanism.links) + 1
    if lang == "uk":
        count = _UK.get(n, f"{n}-ланковий")
        return f"{count} важільний механізм"
    count = _EN.get(n, str(n))
    return f"{count}-link linkage"


def title_in(mechanism: Mechanism, lang: str) -> str:
    """The file's title in `lang` (`title`, `title_uk`), else one built from
    the structure: an English title is not put on a Ukrainian document."""
    if lang == "en" or lang in mechanism.titles:
        return mechanism.title_in(lang)
    return structure_title(mechanism, lang)


def title_warning(mechanism: Mechanism, lang: str) -> str | None:
    """The warning where the title in `lang` is built from the structure."""
    if lang == "en" or lang in mechanism.titles:
        return None
    return (
        f"{mechanism.path}: no title_{lang}; the title is built from the structure: "
        f'{structure_title(mechanism, lang)!r} (write title_{lang} = "..." to give one)'
    )
