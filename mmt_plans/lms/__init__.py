"""Quizzes for a course site: Moodle XML (and GIFT) from answer keys.

Pure writers with no words of their own: every visible word comes in through
the data (the catalogue's [lms] table is used by the caller, `quiz_from_batch`)."""

from __future__ import annotations

from .quiz import NumericalAnswer, Quiz, QuizCategory, QuizQuestion, gift, moodle_xml

__all__ = ["NumericalAnswer", "Quiz", "QuizCategory", "QuizQuestion", "gift", "moodle_xml"]
