"""Number words, shared by the reading (agent/reading.py) and the parse (agent/parse.py), which a batch driver
imports without the catalogue."""

# Words that name an exact number of things.
NUMERALS = {
    "one": 1,
    "two": 2,
    "three": 3,
    "four": 4,
    "five": 5,
    "six": 6,
    "seven": 7,
    "eight": 8,
    "nine": 9,
    "ten": 10,
    "eleven": 11,
    "twelve": 12,
    "fifteen": 15,
    "twenty": 20,
    "dozen": 12,
}
