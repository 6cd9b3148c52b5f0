"""The literature of the note, one list for both languages (seeds 000, 002,
003): each work once, with its entry in English and in Ukrainian, so that the
two notes cite the same works under the same numbers [n]."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["LITERATURE", "Work", "cite", "entries"]


@dataclass(frozen=True)
class Work:
    """A work the note cites: its key and its entry in each language."""

    key: str
    en: str
    uk: str


LITERATURE: tuple[Work, ...] = (
    Work(
        "dstu3008",
        "DSTU 3008:2015. Information and documentation. Reports in the field of science and technology. Structure and rules of execution. – Kyiv: DP «UkrNDNTs», 2016. – 26 p.",
        "ДСТУ 3008:2015. Інформація та документація. Звіти у сфері науки і техніки. Структура та правила оформлювання. – Київ : ДП «УкрНДНЦ», 2016. – 26 с.",
    ),
    Work(
        "dovbush2018",
        "A.D. Dovbush, N.I. Khomyk, T.A. Dovbush. Theory of Machines and Mechanisms. Guidance book for course projecting. – Ternopil: Ternopil Ivan Pul'uj National Technical University, 2018. – 44 p.",
        "Довбуш А.Д., Хомик Н.І., Довбуш Т.А. Теорія механізмів і машин : навчально-методичний посібник до курсового проектування. – Тернопіль : ТНТУ ім. Івана Пулюя, 2018. – 44 с.",
    ),
    Work(
        "fursina2023",
        "A.D. Fursina, V.H. Shevchenko, S.Iu. Kruzhnova. Theoretical and Applied Mechanics: textbook in 4 parts. Part 2: Theory of Machines and Mechanisms. – Zaporizhzhia: NU «Zaporizhzhia Polytechnic», 2023. – 122 p.",
        "Фурсіна А.Д., Шевченко В.Г., Кружнова С.Ю. Теоретична та прикладна механіка : навчальний посібник : в 4 ч. Ч. 2 : Теорія механізмів і машин. – Запоріжжя : НУ «Запорізька політехніка», 2023. – 122 с.",
    ),
    Work(
        "strilets2025",
        "O.R. Strilets, I.O. Pokhylchuk. Guidelines for the self-study of the discipline «Theory of Machines and Mechanisms». – Rivne: NUWEE, 2025.",
        "Стрілець О.Р., Похильчук І.О. Методичні вказівки для самостійного вивчення дисципліни «Теорія механізмів і машин». – Рівне : НУВГП, 2025.",
    ),
    Work(
        "artobolevskiy1954",
        "I.I. Artobolevskiy. Mechanisms and Machines Theory. – K.: Ukrderzhvydav tekhn. lit-ry, 1954. – 696 p.",
        "Артоболевський І.І. Теорія механізмів і машин. – К. : Укрдержвидав техн. літ-ри, 1954. – 696 с.",
    ),
    Work(
        "kinytskyi2002",
        "Ia.T. Kinytskyi. Mechanisms and Machines Theory. – K.: Naukova dumka, 2002. – 660 p.",
        "Кіницький Я.Т. Теорія механізмів і машин. – К. : Наукова думка, 2002. – 660 с.",
    ),
    Work(
        "koreniako1993",
        "Term Design Work in Mechanisms and Machines Theory: textbook / O.S. Koreniako et al., eds O.S. Koreniako. – Kyiv: Vyscha shkola, 1993. – 332 p.",
        "Курсове проектування з теорії механізмів і машин : підручник / О.С. Кореняко та ін. ; за ред. О.С. Кореняка. – Київ : Вища школа, 1993. – 332 с.",
    ),
    Work(
        "rattan2009",
        "S.S. Rattan. Theory of Machines. – New Delhi: Tata McGraw Hill Education Private Limited, 2009. – 732 p.",
        "Rattan S.S. Theory of Machines. – New Delhi : Tata McGraw Hill Education Private Limited, 2009. – 732 p.",
    ),
    Work(
        "kinytskyi2002p",
        "Ia.T. Kinytskyi. Practical Course of the Theory of Machines and Mechanisms: textbook. – Lviv: Afisha, 2002. – 455 p.",
        "Кіницький Я.Т. Практикум із теорії механізмів і машин : навч. посібник. – Львів : Афіша, 2002. – 455 с.",
    ),
    Work(
        "strilets2006",
        "V.M. Strilets, B.I. Chervonyi, I.T. Shynkarenko, I.O. Pokhylchuk. Practical Course «Theory of Machines and Mechanisms». – Rivne: NUWEE, 2006. – 107 p.",
        "Практикум з курсу «Теорія механізмів і машин» / В.М. Стрілець, Б.І. Червоний, І.Т. Шинкаренко, І.О. Похильчук. – Рівне : НУВГП, 2006. – 107 с.",
    ),
    Work(
        "hlad2012",
        "B.M. Hlad, M.I. Pidhurskyi. Theory of Machines and Mechanisms: study guide. – Ternopil, 2012. – 184 p.",
        "Гладь Б.М., Підгурський М.І. Теорія механізмів і машин : навч. посібник. – Тернопіль, 2012. – 184 с.",
    ),
)


def entries(lang: str) -> list[str]:
    """The references list in `lang`, in the order they are numbered."""
    return [w.uk if lang == "uk" else w.en for w in LITERATURE]


def cite(*keys: str) -> str:
    """ "[2]", "[2, 6]": the numbers of the works `keys` in the list."""
    order = [w.key for w in LITERATURE]
    return "[" + ", ".join(str(order.index(k) + 1) for k in keys) + "]"
