"""Moodle's own parsing of a cloze question (question/type/multianswer/
questiontype.php, `qtype_multianswer_extract_question`), ported to Python's re:
the regexes are Moodle's; PHP's variable-width look-behind
`(?<!\\\\|&|&amp;)` is written as three fixed-width ones, which match the same."""

from __future__ import annotations

import re

ANSWER_ALTERNATIVE_FRACTION_REGEX = r"=|%(-?[0-9]+(?:[.,][0-9]*)?)%"
ANSWER_ALTERNATIVE_ANSWER_REGEX = r".+?(?<!\\)(?<!&)(?<!&amp;)(?=[~#}]|$)"
ANSWER_ALTERNATIVE_FEEDBACK_REGEX = r".*?(?<!\\)(?=[~}]|$)"
ANSWER_ALTERNATIVE_REGEX = (
    "(" + ANSWER_ALTERNATIVE_FRACTION_REGEX + ")?"
    "(" + ANSWER_ALTERNATIVE_ANSWER_REGEX + ")"
    "(#(" + ANSWER_ALTERNATIVE_FEEDBACK_REGEX + "))?"
)
NUMBER_REGEX = r"-?(([0-9]+[.,]?[0-9]*|[.,][0-9]+)([eE][-+]?[0-9]+)?)"
NUMERICAL_ALTERNATIVE_REGEX = "^(" + NUMBER_REGEX + ")(:" + NUMBER_REGEX + ")?$"
ANSWER_TYPE_DEF_REGEX = (
    "(NUMERICAL|NM)|(MULTICHOICE|MC)|(MULTICHOICE_V|MCV)|(MULTICHOICE_H|MCH)|"
    "(SHORTANSWER|SA|MW)|(SHORTANSWER_C|SAC|MWC)|"
    "(MULTICHOICE_S|MCS)|(MULTICHOICE_VS|MCVS)|(MULTICHOICE_HS|MCHS)|"
    "(MULTIRESPONSE|MR)|(MULTIRESPONSE_H|MRH)|(MULTIRESPONSE_S|MRS)|(MULTIRESPONSE_HS|MRHS)"
)
ANSWER_START_REGEX = r"\{([0-9]*):(" + ANSWER_TYPE_DEF_REGEX + "):"
ANSWER_REGEX = (
    ANSWER_START_REGEX + "(" + ANSWER_ALTERNATIVE_REGEX + "(~" + ANSWER_ALTERNATIVE_REGEX + ")*)\\}"
)
ANSWER_REGEX_ANSWER_TYPE_NUMERICAL = 3
ANSWER_REGEX_ALTERNATIVES = 16
ANSWER_ALTERNATIVE_REGEX_FRACTION = 1
ANSWER_ALTERNATIVE_REGEX_ANSWER = 3
NUMERICAL_CORRECT_ANSWER = 1
NUMERICAL_ABS_ERROR_MARGIN = 6


def subquestions(text: str) -> list[dict]:
    """Each sub-question as Moodle extracts it: type, answers, fractions, tolerances."""
    out = []
    answer_re = re.compile(ANSWER_REGEX, re.S)
    alt_re = re.compile("~?" + ANSWER_ALTERNATIVE_REGEX, re.S)
    num_re = re.compile(NUMERICAL_ALTERNATIVE_REGEX, re.S)
    while (m := answer_re.search(text)) is not None:
        numerical = bool(m.group(ANSWER_REGEX_ANSWER_TYPE_NUMERICAL))
        sub = {"numerical": numerical, "answers": [], "fractions": [], "tolerances": []}
        remaining = m.group(ANSWER_REGEX_ALTERNATIVES)
        while (alt := alt_re.search(remaining)) is not None:
            sub["fractions"].append(1.0 if alt.group(ANSWER_ALTERNATIVE_REGEX_FRACTION) == "=" else 0.0)
            answer = alt.group(ANSWER_ALTERNATIVE_REGEX_ANSWER)
            num = num_re.search(answer) if numerical else None
            if num is not None:
                sub["answers"].append(num.group(NUMERICAL_CORRECT_ANSWER))
                sub["tolerances"].append(num.group(NUMERICAL_ABS_ERROR_MARGIN) or "0")
            else:
                sub["answers"].append(answer)
            remaining = remaining.split(alt.group(0), 1)[1]
        out.append(sub)
        text = text.replace(m.group(0), f"{{#{len(out)}}}", 1)
    return out
